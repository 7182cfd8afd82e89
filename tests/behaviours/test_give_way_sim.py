"""The right of way between walkers, in the simulator (room_give_way, with room_pulse saying each
walk and where its walker is): robots really crossing, each walking with its range finder, and
giving way over the radio. The later walker waits only until the first has passed (it sets off
before the first arrives), and nobody touches (the scorer counts robot-robot contacts)."""

from __future__ import annotations

import itertools
import json
from pathlib import Path
from typing import Any

import pytest
from helpers import sim_json

DATA = Path(__file__).parent / "data" / "crossing"
PACKED = {"r1": [-4.2, -2.7], "r2": [-3.4, -2.7], "r3": [-4.2, -1.9], "r4": [-3.4, -1.9]}


def run(capsys: pytest.CaptureFixture[str], scenario: str, *params: str) -> dict[str, Any]:
    return sim_json(capsys, DATA / "give_way.yaml", DATA / f"{scenario}.yaml", params)


@pytest.mark.slow
@pytest.mark.parametrize("look", [1.2, 0.0])
def test_ways_crossing_the_later_walker_goes_once_the_first_has_passed(
        capsys: pytest.CaptureFixture[str], look: float) -> None:
    """r1 east along y = 0 and r2 north along x = 0 reach the crossing together: r2 waits (its id is
    the larger) until r1 is past, then goes while r1 is still walking; with or without range finders."""
    result = run(capsys, "give_way_cross", "goals={r1: [3.0, 0.0], r2: [0.0, 1.5]}", f"look={look}")
    assert result["score"]["robot_collisions"] == 0
    agents = {name: agent["outputs"] for name, agent in result["agents"].items()}
    assert all(agent["outcome"] == "arrived" for agent in result["agents"].values())
    assert agents["r1"]["waited"] < 2.0
    assert 20.0 < agents["r2"]["gone"] < agents["r1"]["took"]


@pytest.mark.slow
def test_a_packed_start_lets_the_walkers_out_one_after_the_other(capsys: pytest.CaptureFixture[str]) -> None:
    """Four robots parked 0.8 m apart in a corner, each walking across the room through where the
    others stand: the one with nobody in its way goes first, each of the others once the walker
    before it is out of the first metres of its way (before that one arrives, and before the limit
    of 90 s), and nobody touches. (Measured: r4 sets off at 1.05 s, r1 at 20.15, r2 at 48.25, r3 at
    64.35; before, with the whole of the first one's way kept clear and no order by who stands in
    whose way, r2-r4 waited out the 45 s limit.)"""
    goals = "goals={r1: [0.5, 2.5], r2: [-3.0, 2.5], r3: [1.0, -2.5], r4: [-1.5, 2.5]}"
    result = run(capsys, "give_way_packed", goals, f"starts={json.dumps(PACKED)}")
    assert result["score"]["robot_collisions"] == 0
    assert all(agent["outcome"] == "arrived" for agent in result["agents"].values())
    agents = {name: agent["outputs"] for name, agent in result["agents"].items()}
    order = sorted(agents, key=lambda r: agents[r]["gone"])
    assert order[0] == "r4" and agents["r4"]["waited"] < 2.0  # on the outside: nobody in its way
    assert all(agents[later]["gone"] < agents[first]["took"] for first, later in itertools.pairwise(order))
    assert all(agent["waited"] < 90.0 for agent in agents.values())
