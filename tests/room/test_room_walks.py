"""Walks to a table (hfsm_behaviours/room/walks.py): the place, the way round what stands, the right of way."""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.room.claims import Rect, footprint
from hfsm_behaviours.room.walks import (
    HALF,
    KEEP,
    TIGHT,
    Scene,
    beyond,
    conflict,
    corridor,
    crowd,
    goes_first,
    left_of,
    place_for,
    places,
    plan_walk,
    shorten,
    standable,
    way_to,
)

TABLE = {"id": "table1", "x": 0.0, "y": 0.0, "yaw": 0, "length": 0.8, "width": 0.5, "toward": [3.5, 0.0]}
coords = st.floats(-3.0, 3.0, allow_nan=False).map(lambda v: round(v, 2))
points = st.tuples(coords, coords)


def test_a_place_beside_a_table_is_at_the_middle_of_a_long_side() -> None:
    assert places(TABLE, (0.0, 0.0)) == [(0.0, 1.2), (0.0, -1.2)]
    turned = {**TABLE, "yaw": 90}
    assert [tuple(round(v, 6) for v in p) for p in places(turned, (1.0, 0.0))] == [(-0.2, 0.0), (2.2, 0.0)]


def test_the_place_taken_is_the_free_side_then_the_nearer() -> None:
    assert place_for(TABLE, (0.0, 0.0), (0.0, -3.0), []) == (0.0, -1.2)
    partner = [(0.1, -1.2)]  # stands at the near side: the walker goes round to the far one
    assert place_for(TABLE, (0.0, 0.0), (0.0, -3.0), partner) == (0.0, 1.2)


def test_a_pair_walking_to_its_table_takes_one_side_each() -> None:
    leader, assistant = (-3.0, 2.0), (-2.5, 2.5)  # both nearer the north side, neither at it
    mine = place_for(TABLE, (0.0, 0.0), leader, [assistant], partner=assistant, leads=True)
    theirs = place_for(TABLE, (0.0, 0.0), assistant, [leader], partner=leader, leads=False)
    assert {mine, theirs} == {(0.0, 1.2), (0.0, -1.2)}
    # both near one side (development room crowded-902): the nearer keeps it, the other goes round
    leader, assistant = (-0.4, 1.3), (0.5, 1.4)
    assert place_for(TABLE, (0.0, 0.0), leader, [assistant], partner=assistant, leads=True) == (0.0, 1.2)
    assert place_for(TABLE, (0.0, 0.0), assistant, [leader], partner=leader, leads=False) == (0.0, -1.2)
    # exactly as near either way: the leader's rule decides, the assistant takes the other side
    assert place_for(TABLE, (0.0, 0.0), (-3.0, 0.0), [], partner=(3.0, 0.0), leads=True) == (0.0, 1.2)
    assert place_for(TABLE, (0.0, 0.0), (3.0, 0.0), [], partner=(-3.0, 0.0), leads=False) == (0.0, -1.2)


@given(points, points, points)
def test_the_two_of_a_pair_never_take_the_same_side(leader: tuple[float, float], assistant: tuple[float, float],
                                                    at: tuple[float, float]) -> None:
    mine = place_for(TABLE, at, leader, [assistant], partner=assistant, leads=True)
    theirs = place_for(TABLE, at, assistant, [leader], partner=leader, leads=False)
    assert mine != theirs


def test_a_way_goes_round_a_table_in_between() -> None:
    scene = Scene(7.0, 5.0, (footprint(TABLE, 0.0, (0.0, 0.0)),))
    path = plan_walk(scene, (-2.0, 0.0), (2.0, 0.0))
    assert path is not None and path[-1] == (2.0, 0.0) and len(path) >= 2
    whole = [(-2.0, 0.0), *path]
    for a, b in itertools.pairwise(whole):
        for k in range(21):
            p = (a[0] + (b[0] - a[0]) * k / 20, a[1] + (b[1] - a[1]) * k / 20)
            assert not scene.tables[0].contains(p, 0.3)


def test_a_way_keeps_off_a_robot_standing_still_and_a_corridor_costs_more() -> None:
    robot = (0.0, 0.0)
    path = plan_walk(Scene(7.0, 5.0, robots=(robot,)), (-2.0, 0.0), (2.0, 0.0))
    assert path is not None and len(path) >= 2
    lane = corridor({**TABLE, "x": 0.0, "y": 1.0, "yaw": 90, "toward": [0.0, 2.5]}, 7.0, 5.0)
    # the lane runs from the table's far end (y = 0.6) to the wall: the way goes round its end
    # (2.8 m more) rather than across it (1.25 m at 4 times the cost)
    round_it = plan_walk(Scene(7.0, 5.0, corridors=(lane,)), (-2.0, 2.0), (2.0, 2.0))
    assert round_it is not None and min(p[1] for p in round_it) <= 0.6
    across = plan_walk(Scene(7.0, 5.0, corridors=(lane,)), (-2.0, 0.0), (2.0, 0.0))
    assert across == [(2.0, 0.0)]


@settings(max_examples=30, deadline=None)
@given(points, points, st.lists(points, max_size=3))
def test_a_way_never_comes_near_a_robot_standing_still(start: tuple[float, float], goal: tuple[float, float],
                                                       robots: list[tuple[float, float]]) -> None:
    robots = [r for r in robots if math.dist(r, start) > KEEP + 0.3 and math.dist(r, goal) > KEEP + 0.3]
    scene = Scene(7.0, 7.0, robots=tuple(robots))
    path = plan_walk(scene, start, goal)
    if path is None:
        return
    assert path[-1] == goal
    for a, b in zip([start, *path], path, strict=False):
        for k in range(21):
            p = (a[0] + (b[0] - a[0]) * k / 20, a[1] + (b[1] - a[1]) * k / 20)
            assert all(math.dist(p, r) >= KEEP - 0.2 for r in robots)


@given(st.lists(points, min_size=1, max_size=4), st.lists(points, min_size=1, max_size=4))
def test_conflict_is_symmetric_and_a_walk_meets_itself(a: list[tuple[float, float]], b: list[tuple[float, float]]) -> None:
    assert conflict(a, b) == conflict(b, a)
    assert conflict(a, a)


def test_walks_far_apart_do_not_conflict_and_crossing_ones_do() -> None:
    assert not conflict([(-3.0, -2.0), (3.0, -2.0)], [(-3.0, 2.0), (3.0, 2.0)])
    assert conflict([(-3.0, 0.0), (3.0, 0.0)], [(0.0, -3.0), (0.0, 3.0)])
    assert conflict([(0.0, 0.0), (3.0, 0.0)], [(0.0, 2 * HALF - 0.01), (3.0, 2 * HALF - 0.01)])


def test_what_is_left_of_a_way_starts_where_the_walker_is() -> None:
    way = [(-3.0, 0.0), (0.0, 0.0), (0.0, 3.0)]
    assert left_of(way, (-1.0, 0.1)) == [(-1.0, 0.1), (0.0, 0.0), (0.0, 3.0)]
    assert left_of(way, (0.1, 2.0)) == [(0.1, 2.0), (0.0, 3.0)]
    assert left_of([(1.0, 1.0)], (1.2, 1.0)) == [(1.2, 1.0)]
    crossing = [(0.0, -3.0), (0.0, 3.0)]  # once past the crossing, the first no longer meets it
    assert conflict(crossing, left_of([(-3.0, 0.0), (3.0, 0.0)], (-1.0, 0.0)))
    assert not conflict(crossing, left_of([(-3.0, 0.0), (3.0, 0.0)], (1.0, 0.0)))


@given(st.lists(points, min_size=2, max_size=5), points)
def test_what_is_left_is_never_more_than_the_way(way: list[tuple[float, float]], at: tuple[float, float]) -> None:
    left = left_of(way, at)
    assert left[0] == at and left[1:] == way[len(way) - len(left) + 1:]


@given(st.floats(0, 100), st.floats(0, 100), st.sampled_from(["r1", "r2", "r10"]), st.sampled_from(["r3", "r4"]))
def test_exactly_one_of_two_walkers_goes_first(t1: float, t2: float, a: str, b: str) -> None:
    assert goes_first((t1, 0, a), (t2, 0, b)) != goes_first((t2, 0, b), (t1, 0, a))


def test_in_a_packed_start_the_walker_with_no_robot_in_its_way_goes_first() -> None:
    packed = {"r1": (-4.2, -2.7), "r2": (-3.4, -2.7), "r3": (-4.2, -1.9), "r4": (-3.4, -1.9)}
    out = [(-4.2, -2.7), (0.5, 2.5)]  # r1, from the inner corner: straight through r4
    free = [(-3.4, -1.9), (-1.5, 2.5)]  # r4, on the outside
    assert crowd(out, [p for r, p in packed.items() if r != "r1"]) == 1
    assert crowd(free, [p for r, p in packed.items() if r != "r4"]) == 0
    assert goes_first((0.0, 0, "r4"), (0.0, 1, "r1"))
    assert crowd([(0.0, 0.0), (3.0, 0.0)], [(1.5, 0.8), (-0.8, 0.0)]) == 0  # beside it, behind it


def test_shortening_keeps_a_clear_way() -> None:
    scene = Scene(7.0, 5.0, (Rect(0.0, 0.0, 1.0, 0.0, 0.4, 0.25),))
    assert shorten([(-2.0, 0.0), (-1.0, 1.0), (0.0, 1.0), (1.0, 1.0), (2.0, 0.0)], scene) == \
        [(-2.0, 0.0), (-1.0, 1.0), (1.0, 1.0), (2.0, 0.0)]


def test_a_place_beyond_a_wall_is_not_taken_the_pair_shares_the_other_side() -> None:
    # generated room open-537: a table 0.42 m from a wall along its long side; its far place is
    # outside the room, and the pair's one-side-each rule sent one robot walking there for ever.
    # Held-out room loss-37000: with both robots then sent to the one free place, the assistant got
    # there first and the leader walked about it for its whole walk (126 s), pushing the table 1.2 m;
    # the assistant heads for an end of the free side instead
    table = {"yaw": 170.0, "length": 0.8}
    at, room = (0.48, 1.25), (8.7, 4.2)
    near = place_for(table, at, (0.0, 0.0), [])
    assert standable(near, room) and not standable(places(table, at)[1], room)
    leader, assistant = (-2.8, -0.47), (-0.49, -1.26)
    assert place_for(table, at, leader, [assistant], partner=assistant, leads=True, room=room) == near
    end = place_for(table, at, assistant, [leader], partner=leader, leads=False, room=room)
    assert end in beyond(table, at, near) and standable(end, room) and math.dist(end, near) > 1.0
    assert place_for(table, at, assistant, [], room=room) == near  # a robot alone: the free place
    middle = place_for(table, (0.0, 0.0), (0.0, -3.0), [])  # both places free: the rule as before
    assert place_for(table, (0.0, 0.0), (0.0, -3.0), [], room=room) == middle


def test_where_no_way_keeps_keep_a_tight_one_is_taken_and_none_through_robots() -> None:
    # a corridor 1.3 m wide between two tables, a robot standing at its middle: KEEP closes it
    tables = (Rect(0.0, 1.4, 1.0, 0.0, 2.0, 0.3), Rect(0.0, -1.4, 1.0, 0.0, 2.0, 0.3))
    scene = Scene(8.0, 5.0, tables, (), ((0.0, 0.2),))
    start, goal = (-3.0, 0.0), (3.0, 0.0)
    assert plan_walk(scene, start, goal) is None
    tight = replace(scene, keep=TIGHT)
    way = plan_walk(tight, start, goal)
    assert way is not None
    line = [start, *way]
    for a, b in itertools.pairwise(line):
        for k in range(21):
            p = (a[0] + (b[0] - a[0]) * k / 20, a[1] + (b[1] - a[1]) * k / 20)
            assert math.dist(p, (0.0, 0.2)) >= TIGHT - 0.01
    # a second robot closes it even at TIGHT: no way at all (the walker waits, machines/room_carry.yaml)
    assert plan_walk(replace(tight, robots=((0.0, 0.2), (0.0, -0.6))), start, goal) is None


def test_a_place_on_another_table_is_not_taken() -> None:
    other = footprint({"id": "t2", "x": 0.0, "y": 1.6, "length": 0.8, "width": 0.5}, 0.0)
    assert place_for(TABLE, (0.0, 0.0), (0.0, 3.0), [], tops=[other]) == (0.0, -1.2)
    assert place_for(TABLE, (0.0, 0.0), (0.0, 3.0), []) == (0.0, 1.2)


def test_with_one_side_on_another_table_the_assistant_heads_for_an_end_of_the_free_side() -> None:
    """Generated room close-34000: both robots of table1's pair headed for its one free place; the
    assistant, finding its leader there, walked about it until its walk timed out (305 s)."""
    other = footprint({"id": "t2", "x": 0.0, "y": 1.6, "length": 0.8, "width": 0.5}, 0.0)
    leader, assistant = (0.0, -3.0), (2.0, -3.0)
    assert place_for(TABLE, (0.0, 0.0), leader, [assistant], partner=assistant, leads=True, tops=[other]) == (0.0, -1.2)
    end = place_for(TABLE, (0.0, 0.0), assistant, [leader], partner=leader, leads=False, tops=[other])
    assert end == pytest.approx((1.0, -0.6))


def test_a_walker_that_may_not_wait_goes_round_the_tables_not_through_them() -> None:
    """Held-out room narrow-37000: a leader boxed in by robots standing near its place for its 40
    plans then walked the straight line to it, through another table, pushing it 0.9 m and turning
    it 60 degrees. Without the robots the way goes round the table; the robots standing on it are
    sensed and stepped round as it walks."""
    table = footprint({"id": "t1", "x": 2.37, "y": 0.09, "yaw": 105.0, "length": 1.01, "width": 0.52}, 0.0)
    start, goal = (0.73, 0.81), (3.53, 0.40)
    other = footprint({"id": "t2", "x": 0.47, "y": -0.1, "yaw": 176.0, "length": 1.39, "width": 0.45}, 0.0)
    robots = ((3.98, 0.83), (3.11, 1.56), (4.3, 1.71), (3.1, -0.89), (1.4, 1.67), (-0.78, -1.45))
    scene = Scene(9.7, 4.8, (table, other), (), robots)
    assert way_to(scene, start, goal, wait=True) is None
    way = way_to(scene, start, goal, wait=False)
    assert way is not None and way[-1] == goal
    for a, b in itertools.pairwise([start, *way]):
        for k in range(21):
            p = (a[0] + (b[0] - a[0]) * k / 20, a[1] + (b[1] - a[1]) * k / 20)
            assert not table.contains(p, 0.3) and not other.contains(p, 0.3)
    free = way_to(Scene(9.7, 4.8, (table, other)), start, goal, wait=True)
    assert free is not None and free[-1] == goal
