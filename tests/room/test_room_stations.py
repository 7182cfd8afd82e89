"""Grouping ties in a room (hfsm_behaviours/room/stations.py): with no history, pairs stand at their tables."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.room.plan import make_room_plan
from hfsm_behaviours.room.recovery import job_of
from hfsm_behaviours.room.stations import room_ties, stations
from hfsm_behaviours.tararc.grouping import Group, Robot
from hfsm_behaviours.tararc.help import lend


@given(st.integers(2, 5), st.integers(0, 3), st.permutations(list(range(13))), st.integers(0, 3))
def test_every_table_is_carried_by_the_pair_standing_at_it(k: int, extra: int, order: list[int], turn: int) -> None:
    tables = [{"id": f"table{i + 1}", "x": 4.0 * i - 8.0, "y": 0.0, "yaw": 90 * turn, "length": 0.8, "width": 0.5}
              for i in range(k)]
    spots = []
    for t in tables:
        ux, uy = round(math.cos(math.radians(t["yaw"]))), round(math.sin(math.radians(t["yaw"])))
        spots += [(t["x"] - s * uy * 1.2, t["y"] + s * ux * 1.2) for s in (1, -1)]
    spots += [(4.0 * i - 8.0 + 2.0, 3.0) for i in range(extra)]  # free robots, between the tables
    names = [f"r{n + 1}" for n in order if n < len(spots)]
    where = dict(zip(names, spots, strict=True))
    states = {r: {"x": x, "y": y, "energy": 1.0, "record": {}} for r, (x, y) in where.items()}
    plan = make_room_plan(states, tables, {"width": 20.0, "depth": 8.0})
    for r, (x, y) in where.items():
        job = job_of(plan, r, [], [], {})
        assert job is not None
        if job["role"] in ("leader", "assistant"):
            assert math.dist((x, y), job["at"]) < 1.3


def test_a_robot_nearer_its_own_table_than_another_standing_pair_seeds_first() -> None:
    robots = {"r1": {"x": 0.0, "y": 3.0}, "r2": {"x": 0.0, "y": 1.2}, "r3": {"x": 5.0, "y": 1.2}}
    tables = [{"id": "table1", "x": 0.0, "y": 0.0}, {"id": "table2", "x": 5.0, "y": 0.0}]
    assert stations(robots, tables) == {"r1": ("table1", 1.8), "r2": ("table1", 0.0), "r3": ("table2", 0.0)}
    ties = room_ties(robots, tables)
    assert sorted(robots, key=ties.seed)[:2] == ["r2", "r3"]
    assert sorted(["r1", "r3"], key=lambda r: ties.partner("r2", r)) == ["r1", "r3"]  # r3 stands at table2


def test_keep_lends_only_members_beyond_the_pair() -> None:
    groups = [Group("a", ("a",)), Group("b", ("b", "c", "d"))]
    where = {r: Robot(r, x, 0.0) for r, x in (("a", 0.0), ("b", 5.0), ("c", 1.0), ("d", 9.0))}
    assert [t.member for t in lend(groups, 0, 2, where)] == ["c"]
    assert [t.member for t in lend(groups, 0, 2, where, keep=2)] == ["d"]


def test_a_robot_beside_one_table_near_the_end_of_another_belongs_to_the_first() -> None:
    # the campaign's K = 5, N = 13 room (seed 102): r7 stands at table4's long side, 1.2 m from its
    # centre but 1.15 m from table5's (it is near table5's end): by the places, r7 is table4's
    tables = [{"id": "table4", "x": -0.86, "y": -1.95, "yaw": 90, "length": 0.9, "width": 0.5},
              {"id": "table5", "x": -3.2, "y": -1.71, "yaw": 0, "length": 0.7, "width": 0.5}]
    robots = {"r7": {"x": -2.06, "y": -1.89}, "r8": {"x": 0.34, "y": -1.89},
              "r9": {"x": -3.38, "y": -0.51}, "r10": {"x": -3.38, "y": -2.91}}
    assert {r: s[0] for r, s in stations(robots, tables).items()} == {
        "r7": "table4", "r8": "table4", "r9": "table5", "r10": "table5"}
    states = {r: {**p, "energy": 1.0, "record": {}} for r, p in robots.items()}
    plan = make_room_plan(states, tables, {"width": 10.5, "depth": 7.25})
    assert sorted((g["task"]["id"], sorted(g["members"])) for g in plan["groups"]) == [
        ("table4", ["r7", "r8"]), ("table5", ["r10", "r9"])]


def test_a_free_robot_nearer_the_centre_does_not_take_the_place_of_the_pair() -> None:
    # the target room of seed 48: r8 stands free 1.17 m from table1's centre, r2 at its side 1.2 m
    tables = [{"id": "table1", "x": 0.58, "y": -2.17, "yaw": 270, "length": 0.7, "width": 0.55}]
    robots = {"r1": {"x": 1.78, "y": -2.12}, "r2": {"x": -0.62, "y": -2.12}, "r8": {"x": 0.92, "y": -1.05}}
    ties = room_ties(robots, tables)
    assert sorted(["r2", "r8"], key=lambda r: ties.partner("r1", r)) == ["r2", "r8"]
