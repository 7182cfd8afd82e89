"""Tables with no room to stand at one long side (hfsm_behaviours/room/cramped): one robot of the pair
slides it alone from the free side, the other waits; both agree who, from the plan and the news."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.room.cramped import free_place, side_room, slider_of
from hfsm_behaviours.room.plan import make_room_plan
from hfsm_behaviours.room.recovery import job_of

# generated room open-537: the table's north side 0.43 m from the wall
OPEN_537 = {"id": "table1", "kind": "table", "x": 0.48, "y": 1.25, "yaw": 170.0, "length": 1.27, "width": 0.86}
ROOM = {"width": 8.7, "depth": 4.2}


def states(*places: tuple[str, float, float]) -> dict[str, dict[str, object]]:
    return {r: {"x": x, "y": y, "energy": 1.0, "record": {}} for r, x, y in places}


def test_a_table_whose_side_is_near_a_wall_has_its_free_place_on_the_other_side() -> None:
    north, south = sorted(side_room(OPEN_537, 8.7, 4.2))
    assert 0.4 < north < 0.45 and 2.9 < south < 3.0
    place = free_place(OPEN_537, 8.7, 4.2)
    assert place and place[1] < OPEN_537["y"] - 1.0  # beside the south side


def test_a_table_with_room_on_both_sides_or_neither_is_carried_as_a_pair() -> None:
    assert free_place({**OPEN_537, "y": 0.0}, 8.7, 4.2) == []
    assert free_place({**OPEN_537, "y": 0.0}, 8.7, 1.6) == []  # neither side has room: no slide


def test_the_robot_told_it_started_nearer_the_free_place_slides_then_the_other() -> None:
    starts = {"r1": {"x": -2.8, "y": -0.47}, "r2": {"x": -0.49, "y": -1.26}}
    free = free_place(OPEN_537, 8.7, 4.2)
    assert slider_of(free, "r1", "r2", starts, "c_", []) == "r2"
    assert slider_of(free, "r1", "r2", starts, "c_", ["c_/r2"]) == "r1"
    assert slider_of(free, "r1", "r2", starts, "c_1_", ["c_/r2"]) == "r2"


def test_open_537_one_robot_slides_and_its_partner_waits() -> None:
    plan = make_room_plan(states(("r1", -2.8, -0.47), ("r2", -0.49, -1.26)), [OPEN_537], ROOM)
    jobs = {r: job_of(plan, r, [], [], {}) for r in ("r1", "r2")}
    assert sorted(str(j["slide"]) for j in jobs.values() if j) == ["me", "partner"]
    slider = next(r for r, j in jobs.items() if j and j["slide"] == "me")
    assert slider == "r2"
    spent = [f"{jobs['r2']['channel']}/r2"] if jobs["r2"] else []
    again = {r: job_of(plan, r, [], [], {}, spent) for r in ("r1", "r2")}
    assert again["r1"] and again["r1"]["slide"] == "me" and again["r2"] and again["r2"]["slide"] == "partner"


@given(st.floats(-3.0, 3.0), st.floats(-1.5, 1.5), st.floats(-180, 180), st.lists(st.text("r12", min_size=0, max_size=3)))
def test_exactly_one_robot_of_a_cramped_pair_slides(x: float, y: float, yaw: float, said: list[str]) -> None:
    table = {**OPEN_537, "x": x, "y": y, "yaw": yaw}
    plan = make_room_plan(states(("r1", -2.8, -0.47), ("r2", 2.0, -1.26)), [table], ROOM)
    first = job_of(plan, "r1", [], [], {})
    assert first is not None
    spent = [f"{first['channel']}/r{s}" for s in said if s in "12"]
    jobs = [job_of(plan, r, [], [], {}, spent) for r in ("r1", "r2")]
    slides = sorted(str(j["slide"]) for j in jobs if j)
    assert slides in (["", ""], ["me", "partner"])
    assert (slides == ["", ""]) == (plan["tables"]["table1"]["free"] == [])
