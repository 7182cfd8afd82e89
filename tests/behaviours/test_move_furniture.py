"""The main job, end to end: two robots move the table to a wall, through `hfsm-run` itself."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hfsm.cli.run import main

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_two_robots_move_the_table_to_a_wall(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = main([str(ROOT / "machines" / "move_furniture.yaml"), "--json", "--out", str(tmp_path), "--quiet"])
    out, err = capsys.readouterr()
    result = json.loads(out)
    assert code == 0, err
    assert {a: r["outcome"] for a, r in result["agents"].items()} == {"r1": "at_wall", "r2": "at_wall"}
    assert sorted(r["outputs"]["role"] for r in result["agents"].values()) == ["assistant", "leader"]
    score = result["score"]
    assert score["success"] and not score["dropped"] and score["robot_collisions"] == 0
    assert score["table_wall_distance"] <= 0.15
    assert score["time"] < 12 * 60, "no slower than the paper's no-wait time"
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == ["opposite_long_side-seed0.jsonl", "opposite_long_side-seed0.mp4", "opposite_long_side-seed0.png"]
    records = [json.loads(line) for line in (tmp_path / "opposite_long_side-seed0.jsonl").read_text().splitlines()]
    assert records[-1]["kind"] == "exit" and records[-1]["path"] == ["move_furniture"]


@pytest.mark.slow
def test_the_same_seed_gives_the_same_trace_byte_for_byte(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    traces = []
    for run in ("a", "b"):
        out = tmp_path / run
        argv = [str(ROOT / "machines" / "move_furniture.yaml"), "--scenario", "same_side", "--seed", "7"]
        assert main([*argv, "--no-video", "--out", str(out), "--quiet"]) == 0
        traces.append((out / "same_side-seed7.jsonl").read_bytes())
    capsys.readouterr()
    assert traces[0] == traces[1] and len(traces[0]) > 10_000
