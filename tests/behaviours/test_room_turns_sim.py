"""Two tables side by side, their long sides 0.8 m apart (tests/behaviours/data/tight): both ways to a
wall overlap, so the pairs take turns (claims.turns: table2's pair waits until table1 is done, heard
over the radio), and the room is cleared with no robot-robot contact."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from helpers import hfsm_run

DATA = Path(__file__).parent / "data" / "tight"


@pytest.mark.slow
def test_pairs_whose_ways_overlap_take_turns_and_never_touch(capsys: pytest.CaptureFixture[str],
                                                             tmp_path: Path) -> None:
    trace = tmp_path / "trace.jsonl"
    code, out, _ = hfsm_run(capsys, "machines/clear_room.yaml", "--scenario", DATA / "side_by_side.yaml",
                            "--seed", 0, "--json", "--no-video", "--quiet", "--progress", 0,
                            "--trace", trace)
    assert code == 0
    score = json.loads(out)["score"]
    assert score["success"] and score["robot_collisions"] == 0
    records = [json.loads(line) for line in trace.read_text(encoding="utf-8").splitlines()]
    first: dict[str, float] = {}
    for r in records:
        if r.get("kind") == "enter" and r["path"] == ["clear_room", "work"]:
            first.setdefault(r["agent"], r["t"])
    done = min(r["t"] for r in records if r.get("kind") == "enter" and r["path"] == ["clear_room", "finished"])
    assert sorted(agent for agent, t in first.items() if t > done) == ["r3", "r4"]  # table2's pair, after table1
