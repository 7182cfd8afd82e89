"""Failures anywhere: a table whose pair is gone is waited for by no other table's turn
(hfsm_behaviours.room.plan.unmanned, room_assign's `turn`), so the room never waits out its
time limit on a table nobody can carry: the others go on, and their robots come for it after."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from hfsm_behaviours.room.plan import job_of, make_room_plan, unmanned
from hfsm_behaviours.teamwork.room import room_assign

ROOM = {"width": 7.0, "depth": 5.0}
SIDE_BY_SIDE = [  # their long sides 0.8 m apart: the pairs take turns
    {"id": "table1", "kind": "table", "x": 0.0, "y": -0.65, "yaw": 0, "length": 0.8, "width": 0.5, "priority": 1},
    {"id": "table2", "kind": "table", "x": 0.0, "y": 0.65, "yaw": 0, "length": 0.8, "width": 0.5, "priority": 2},
]
ROBOTS = {"r1": (0.0, -1.85), "r2": (-0.6, 0.0), "r3": (0.6, 0.0), "r4": (0.0, 1.85)}
START = {"x": 0.0, "y": 0.0, "yaw": 0.0}


@dataclass
class Ctx:
    agent: str


def plan() -> dict[str, Any]:
    states = {r: {"x": x, "y": y, "energy": 1.0, "record": {}} for r, (x, y) in ROBOTS.items()}
    return make_room_plan(states, SIDE_BY_SIDE, ROOM)


def assign(p: dict[str, Any], me: str, lost: list[str], done: list[str]) -> dict[str, Any]:
    got = room_assign.fn(Ctx(me), plan=p, lost=lost, done=done, seen={}, start=START)
    assert not isinstance(got, str)
    job: dict[str, Any] = got.outputs["job"]
    return job


def pairs(p: dict[str, Any], lost: list[str]) -> dict[str, tuple[str, str]]:
    return {r: (j["role"], j["table"]) for r in ROBOTS if (j := job_of(p, r, lost, [], {})) is not None}


def test_a_table_waits_for_an_earlier_one_while_that_one_has_its_pair() -> None:
    p = plan()
    first, second = sorted(SIDE_BY_SIDE, key=lambda t: len(p["tables"][t["id"]].get("after", [])))
    assert p["tables"][second["id"]]["after"] == [first["id"]]
    waiter = next(r for r, (role, table) in pairs(p, []).items() if table == second["id"] and role == "leader")
    assert assign(p, waiter, [], [])["turn"] == [first["id"]]


def test_a_table_whose_pair_failed_is_waited_for_by_no_turn() -> None:
    p = plan()
    first, second = sorted(SIDE_BY_SIDE, key=lambda t: len(p["tables"][t["id"]].get("after", [])))
    gone = [r for r, (_, table) in pairs(p, []).items() if table == first["id"]]
    assert len(gone) == 2
    jobs = pairs(p, gone)
    waiter = next(r for r, (role, table) in jobs.items() if table == second["id"] and role == "leader")
    job = assign(p, waiter, gone, [])
    assert unmanned(p, gone, []) == [first["id"]] and unmanned(p, [], []) == []
    assert job["role"] == "leader" and job["turn"] == []
    # once its table is done, the pair is lent to the one left: nobody waits out the limit
    after = job_of(p, waiter, gone, [second["id"]], {})
    assert after is not None and (after["role"], after["table"]) in {("leader", first["id"]), ("assistant", first["id"])}
