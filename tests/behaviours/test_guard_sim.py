"""The safety guard in the simulator (hfsm_behaviours/drive/guard.py): a blind walker (its range
finder's `look` 0, so nothing steers it) going to and fro across the corridor of a pair carrying its
table to the wall. Guarded, the walker and the carrying pair stop short of each other, and the table
still reaches its wall; unguarded, the same walk touches the pair."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from helpers import hfsm_run

from hfsm_behaviours import simworld

DATA = Path(__file__).parent / "data" / "guard"


def cross(capsys: pytest.CaptureFixture[str]) -> dict[str, Any]:
    code, out, _ = hfsm_run(capsys, DATA / "carry_cross.yaml", "--scenario", DATA / "pair_crossed.yaml",
                            "--seed", 0, "--json", "--no-video", "--quiet", "--progress", 0,
                            "--max-time", 400, "--param", "look=0")
    assert code == 0
    result: dict[str, Any] = json.loads(out)
    return result


@pytest.mark.slow
def test_a_blind_walker_crossing_a_carrying_pair_never_touches_it(capsys: pytest.CaptureFixture[str]) -> None:
    result = cross(capsys)
    assert result["score"]["robot_collisions"] == 0
    assert result["agents"]["r2"]["outcome"] == result["agents"]["r3"]["outcome"] == "at_wall"
    assert result["score"]["table_wall_distance"] <= 0.15


@pytest.mark.slow
def test_unguarded_the_same_walk_touches_the_pair(capsys: pytest.CaptureFixture[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(simworld, "GUARDED", False)
    assert cross(capsys)["score"]["robot_collisions"] > 0
