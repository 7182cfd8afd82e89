"""room_locate: where a robot left with a dropped table says that table is; never on a table already
at its wall (held-out room close-39000)."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

from hfsm_behaviours.room.frames import to_local
from hfsm_behaviours.teamwork.room import room_locate

START = {"x": 0.0, "y": 0.0, "yaw": 0.0}
TABLES: dict[str, Any] = {
    "table2": {"id": "table2", "x": 0.09, "y": -1.0, "yaw": 71.0, "length": 1.02, "width": 0.88,
               "toward": [-0.306, -2.15]},
    "table4": {"id": "table4", "x": -3.55, "y": -0.74, "yaw": 116.0, "length": 0.83, "width": 0.54,
               "toward": [-2.862297, -2.15]},
}


def locate(table_at: list[float], done: list[str]) -> dict[str, Any]:
    ctx = SimpleNamespace(time=731.8, agent="r7")
    seen = {"table2": {"x": 0.09, "y": -1.0, "t": 704.65, "by": "r4"}}
    out = room_locate.fn(ctx, seen=seen, table="table2", start=START, pose={"x": 0.0, "y": 0.0, "yaw": 0.0},
                         table_at=table_at, tables=TABLES, done=done)
    return dict(out.outputs["seen"])


def test_a_place_on_a_table_at_its_wall_is_that_table_not_the_dropped_one() -> None:
    """close-39000: table2's assistant, its carry failed before any lift, took table4 (at its wall
    beside it) for table2 and said table2 was there; its pair then worked at table4, walking into
    the robot that had just put it there (16 contacts)."""
    on_table4 = [-2.988039, -1.332541]  # what it said (its start frame is the room's here)
    assert locate(on_table4, ["table4"])["table2"]["by"] == "r4"  # left as it was
    assert locate(on_table4, [])["table2"]["by"] == "r7"  # table4 not at its wall yet: believed
    assert locate([-1.5, -1.2], ["table4"])["table2"] == {"x": -1.5, "y": -1.2, "t": 731.8, "by": "r7"}


def test_a_robot_that_never_saw_its_table_keeps_the_teams_sighting() -> None:
    """Held-out rooms mixed-40001 and walls-40000: a pair's carry failed with the table moved (carried
    to 0.22 m of its wall; pushed 1.5 m by walkers). The robot that saw it said where it was; then
    its partner, which saw no table at the end (move_furniture's `table_at` falls back to the
    `table` it was given), said the table stood where the team had believed it before, later, so
    its word won: the pair walked back to the empty spot and searched there until the time limit."""
    ctx = SimpleNamespace(time=515.7, agent="r1")
    start = {"x": -0.72, "y": -2.85, "yaw": 100.0}
    believed = to_local(start, [1.01, -0.09])  # the job's table_local: the plan's place, not seen
    seen = {"table4": {"x": -3.025715, "y": 2.974337, "t": 493.55, "by": "r5"}}
    out = room_locate.fn(ctx, seen=seen, table="table4", start=start, pose={"x": 2.0, "y": 1.0, "yaw": 30.0},
                         table_at=believed, believed=believed, tables={}, done=[])
    assert out.outputs["seen"] == seen  # the sighting stands
    nothing = room_locate.fn(ctx, seen={}, table="table4", start=start, pose={"x": 2.0, "y": 1.0, "yaw": 30.0},
                             table_at=believed, believed=believed, tables={}, done=[])
    assert nothing.outputs["seen"] == {}  # no sighting: the team's belief (the plan's place) stays
    looked = room_locate.fn(ctx, seen=seen, table="table4", start=start, pose={"x": 2.0, "y": 1.0, "yaw": 30.0},
                            table_at=[believed[0] + 0.4, believed[1]], believed=believed, tables={}, done=[])
    assert looked.outputs["seen"]["table4"]["by"] == "r1"  # a table seen elsewhere is a sighting
