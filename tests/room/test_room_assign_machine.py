"""machines/room_assign.yaml, the room's recovery decisions as a machine over pure steps, decides
what `room.recovery.job_of` decides, for any news the team may hear."""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.program import Program, machine_params
from hfsm.runtime.run import RunOptions, run
from hfsm.world import NullWorld
from hfsm_behaviours.room.frames import to_local
from hfsm_behaviours.room.plan import make_room_plan
from hfsm_behaviours.room.recovery import job_of
from tests.room.test_room_plan import NEWS, ROOM, SIX, TASKS

MACHINE = "room_assign"
START = {"x": 0.5, "y": -0.5, "yaw": 30.0}


@cache
def program() -> tuple[Program, Any]:
    registry = Registry.discover()
    loaded = load([Path(__file__).resolve().parents[2] / "machines" / f"{MACHINE}.yaml"], registry=registry)
    return Program(loaded.machines, registry, 0.05), loaded.roots[0]


def assign(robot: str, **params: Any) -> tuple[str, dict[str, Any]]:
    prog, top = program()
    options = RunOptions(top.name, [robot], machine_params(top, params), 0, 60.0, [])
    result = run(prog, NullWorld(), options, None).agents[robot]
    assert result.time == 0  # every step is pure: the decision takes no time
    return str(result.outcome), dict(result.outputs.get("job", {}))


@settings(max_examples=40, deadline=None)
@given(NEWS, st.sampled_from(sorted(SIX)))
def test_the_machine_decides_what_job_of_decides(news: dict[str, list[str]], robot: str) -> None:
    plan = make_room_plan(SIX, TASKS, ROOM)
    seen = {"table1": {"x": -2.0, "y": 0.3, "t": 1.0, "by": "r1"}}
    outcome, job = assign(robot, plan=plan, start=START, seen=seen, **news)
    expected = job_of(plan, robot, news["lost"], news["done"], {"table1": [-2.0, 0.3]}, news["spent"],
                      news["sliding"])
    if expected is None:
        assert outcome == "excluded"
        return
    assert outcome == "assigned"
    local = {k: job.pop(k) for k in ("table_local", "toward_local", "turn")}
    assert job == expected
    assert local["table_local"] == (to_local(START, expected["at"]) if expected["at"] else [])
