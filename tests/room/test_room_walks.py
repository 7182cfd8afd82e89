"""Walks to a table (hfsm_behaviours/room/walks.py): the place, the way round what stands, the right of way."""

from __future__ import annotations

import itertools
import math

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.room.claims import Rect, footprint
from hfsm_behaviours.room.walks import (
    HALF,
    KEEP,
    Scene,
    conflict,
    corridor,
    goes_first,
    place_for,
    places,
    plan_walk,
    shorten,
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


@given(st.floats(0, 100), st.floats(0, 100), st.sampled_from(["r1", "r2", "r10"]), st.sampled_from(["r3", "r4"]))
def test_exactly_one_of_two_walkers_goes_first(t1: float, t2: float, a: str, b: str) -> None:
    assert goes_first((t1, a), (t2, b)) != goes_first((t2, b), (t1, a))


def test_shortening_keeps_a_clear_way() -> None:
    scene = Scene(7.0, 5.0, (Rect(0.0, 0.0, 1.0, 0.0, 0.4, 0.25),))
    assert shorten([(-2.0, 0.0), (-1.0, 1.0), (0.0, 1.0), (1.0, 1.0), (2.0, 0.0)], scene) == \
        [(-2.0, 0.0), (-1.0, 1.0), (1.0, 1.0), (2.0, 0.0)]
