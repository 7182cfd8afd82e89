"""Grouping ties in a room (behaviours/room/stations.py): with no history, pairs stand at their tables."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from behaviours.room.plan import job_of, make_room_plan
from behaviours.room.stations import room_ties, stations
from behaviours.tararc.grouping import Group, Robot
from behaviours.tararc.help import lend


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
    assert stations(robots, tables) == {"r1": ("table1", 3.0), "r2": ("table1", 1.2), "r3": ("table2", 1.2)}
    ties = room_ties(robots, tables)
    assert sorted(robots, key=ties.seed)[:2] == ["r2", "r3"]
    assert sorted(["r1", "r3"], key=lambda r: ties.partner("r2", r)) == ["r1", "r3"]  # r3 stands at table2


def test_keep_lends_only_members_beyond_the_pair() -> None:
    groups = [Group("a", ("a",)), Group("b", ("b", "c", "d"))]
    where = {r: Robot(r, x, 0.0) for r, x in (("a", 0.0), ("b", 5.0), ("c", 1.0), ("d", 9.0))}
    assert [t.member for t in lend(groups, 0, 2, where)] == ["c"]
    assert [t.member for t in lend(groups, 0, 2, where, keep=2)] == ["d"]
