"""A slice of issue 20's campaign in the suite (slow): rooms from the generator (hfsm_sim.roomgen)
with seeds never used while developing, each judged as the bench judges it (tools/room/trials.py).

The rule, fixed before any of them was run, keeps the slice near two minutes: in the strata `open`
and `failures`, the first room from seed 500 on with one table and two robots (for `failures`, one
whose first failure comes before 40 s, so that one robot is left). Each must be a success (its
table at a wall, no robot-robot contact). (Ending `stuck` when no pair is left
is tested world-free, tests/machines/clear_room.test.yaml.) Also: a room's trace carries what the monitor draws of each
robot's belief, and is the same byte for byte for the same seed."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.simworld import SimWorld  # noqa: E402
from hfsm_behaviours.trial import TrialSpec, run_trial  # noqa: E402
from hfsm_sim import World  # noqa: E402
from hfsm_sim.roomgen import draw, write  # noqa: E402
from hfsm_sim.scenario import scenario_from_dict  # noqa: E402
from tools.room.trials import RoomTrial, run_room_trial  # noqa: E402

SLICE = [("open", 537), ("failures", 520)]


def _small(stratum: str, seed: int) -> bool:
    data = draw(seed, stratum)
    early = stratum != "failures" or (bool(data["failures"]) and data["failures"][0].get("at", 1e9) < 40)
    return len(data["tables"]) == 1 and len(data["robots"]) == 2 and early


def test_the_slice_follows_its_rule() -> None:
    for stratum, seed in SLICE:
        assert _small(stratum, seed) and not any(_small(stratum, s) for s in range(500, seed))


def _run(stratum: str, seed: int) -> dict[str, Any]:
    return run_room_trial(RoomTrial(stratum, stratum, seed, draw(seed, stratum), max_time=900.0))


@pytest.mark.slow
def test_a_generated_room_is_cleared_without_contact() -> None:
    # a strict expected failure on the room's first branch (0.30 m off at 900 s, 6 contacts); cleared
    # without a contact since the walks look and main's fixes were merged in
    result = _run(*SLICE[0])
    assert result["success"], {k: result[k] for k in ("distances", "collisions", "error", "time")}


@pytest.mark.slow
def test_a_generated_room_whose_robot_fails_early_is_finished_by_the_survivor() -> None:
    # r1 fails at 19.6 s at the table; r2, hearing it silent on the team's heartbeat too, slides
    # table1 to its wall alone (`confirm`, `solo`): the team finishes with what is left
    result = _run(*SLICE[1])
    assert result["success"] and result["time"] < 600, {k: result[k] for k in ("distances", "stuck", "error", "time")}
    assert [f["robot"] for f in result["failures"]] == ["r1"]


@pytest.mark.slow
def test_a_room_trace_carries_beliefs_and_is_the_same_for_the_same_seed(tmp_path: Path) -> None:
    scenario = tmp_path / "walls-500.yaml"
    write(scenario, draw(500, "walls"))
    traces = []
    for n in range(2):
        trace = tmp_path / f"t{n}.jsonl"
        spec = TrialSpec(str(ROOT / "machines" / "clear_room.yaml"), str(scenario), 3, {}, 12.0, trace=str(trace))
        assert run_trial(spec).time == pytest.approx(12.0, abs=0.1)
        traces.append(trace.read_bytes())
    assert traces[0] == traces[1]
    records = [json.loads(line) for line in traces[0].decode().splitlines()]
    poses = [r for r in records if r["kind"] == "pose"]
    sensed = poses[-1]["sensed"]
    assert sorted(sensed) == ["r1", "r2", "r3", "r4"] and all("start" in s for s in sensed.values())
    drawn = [r["vars"]["drawn"] for r in records if r["kind"] == "event" and "drawn" in r.get("vars", {})]
    assert drawn and drawn[-1]["rects"] and drawn[-1]["rects"][0][-1] == "table1 corridor"


def test_the_pose_records_carry_what_each_robot_last_sensed_in_its_own_frame() -> None:
    data = {**draw(500, "walls"), "jitter": {"position": 0.0, "yaw": 0.0}}
    data["robots"] = {"r1": {"x": -1.0, "y": 0.0, "yaw": 0.0}, "r2": {"x": -3.0, "y": 0.0, "yaw": 0.0}}
    data["tables"] = [{"id": "table1", "x": 0.0, "y": 0.0, "yaw": 90.0, "length": 0.8, "width": 0.5}]
    world = SimWorld(World(scenario_from_dict(data), 0))
    try:
        world.start(["r1", "r2"], 0.05)
        seen = world.read_input("r1", "tables_in_view", 0)
        assert seen and abs(seen[0]["x"] - 1.0) < 0.15  # 1 m ahead of where it started
        sensed = world.trace_records(0)[0]["sensed"]
        assert sensed["r1"] == {"start": [-1.0, 0.0, 0.0], "tables_in_view": {"t": 0.0, "value": seen}}
        assert "r2" not in sensed  # read nothing yet
    finally:
        world.close()
