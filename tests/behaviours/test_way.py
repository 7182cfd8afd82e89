"""The assistant's way round its table (hfsm_behaviours.approach.way), world-free: given a table, where
the robot stands and the things its range finder senses, which way it walks."""

from __future__ import annotations

import itertools
import math

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.approach.frames import Point, Side, from_table_frame, sides, table_frame
from hfsm_behaviours.approach.way import AHEAD, CLEAR, choose, first_block, in_way, route, short_of
from hfsm_sim.perception.table_rect import TableRect

TABLE = TableRect(True, x=1.0, y=2.0, axis=0.3, length=1.2, width=0.6)
MARGIN, GAP = 0.5, 0.35


def far_side(rect: TableRect) -> Side:
    """The +y long side (in the table's frame): the target; the leader stands at the -y side."""
    return next(s for s in sides(rect)[:2] if table_frame(rect, s.middle)[1] > 0)


def at(rect: TableRect, x: float, y: float) -> Point:
    return from_table_frame(rect, (x, y))


def local(rect: TableRect, points: list[Point]) -> list[Point]:
    return [tuple(round(v, 6) for v in table_frame(rect, p)) for p in points]  # type: ignore[misc]


def test_with_nothing_sensed_the_way_is_the_blind_one() -> None:
    robot = at(TABLE, 0.3, -1.2)
    step = choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, [])
    assert not step.stop
    assert step.points == route(TABLE, robot, far_side(TABLE), MARGIN, GAP)
    assert local(TABLE, step.points) == [(1.1, -0.8), (1.1, 0.8), (0.0, 0.65)]


def test_a_robot_on_the_near_corner_sends_it_round_the_other_end() -> None:
    robot = at(TABLE, 0.3, -1.2)
    waiting = at(TABLE, 1.0, -0.85)
    step = choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, [waiting])
    assert not step.stop
    assert local(TABLE, step.points)[0][0] < 0  # the -x end
    assert first_block(robot, step.points, [waiting], CLEAR) is None


def test_the_leader_at_its_side_is_never_on_the_way_taken() -> None:
    leader = at(TABLE, 0.0, -0.45)
    for x in (-1.5, -0.6, -0.1, 0.1, 0.6, 1.5):
        for y in (-1.6, -1.0, -0.8):
            robot = at(TABLE, x, y)
            step = choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, [leader])
            legs = [robot, *step.points]
            assert all(not in_way(leader, a, b, CLEAR) for a, b in itertools.pairwise(legs)), (x, y)


def test_a_robot_at_the_end_with_one_corner_blocked_steps_round_it() -> None:
    robot = at(TABLE, 1.3, 0.0)
    waiting = at(TABLE, 1.15, 0.8)  # on the corner it would walk to
    step = choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, [waiting])
    assert first_block(robot, step.points, [waiting], CLEAR) is None or step.stop
    if not step.stop:
        assert len(step.points) >= 2


def test_robots_on_both_ways_stop_the_walk_short() -> None:
    robot = at(TABLE, 0.0, -1.3)
    things = [at(TABLE, x, y) for x in (-1.6, -1.1, -0.6, 0.6, 1.1, 1.6) for y in (-1.3, -0.8, -0.3, 0.3, 0.8)]
    step = choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, things)
    assert step.stop
    stop = step.points[0]
    assert all(math.dist(stop, p) >= CLEAR - 1e-6 or math.dist(robot, p) < CLEAR for p in things)


def test_short_of_stops_clear_of_a_thing_ahead_and_ignores_one_behind() -> None:
    robot, goal = (0.0, 0.0), (2.0, 0.0)
    assert short_of(robot, [goal], [(1.0, 0.1)], 0.45) == (1.0 - math.sqrt(0.45 ** 2 - 0.01), 0.0)
    assert short_of(robot, [goal], [(-0.3, 0.0)], 0.45) == goal
    assert not in_way((-0.3, 0.0), robot, goal, 0.45)


points = st.tuples(st.floats(-2.5, 2.5), st.floats(-2.5, 2.5))


@settings(max_examples=200, deadline=None)
@given(x=st.floats(-2.0, 2.0), y=st.floats(-2.0, -0.6), seen=st.lists(points, max_size=6),
       axis=st.floats(-math.pi, math.pi))
def test_a_way_walked_has_no_thing_sensed_near_in_its_way(x: float, y: float, seen: list[Point],
                                                     axis: float) -> None:
    rect = TableRect(True, x=0.0, y=0.0, axis=axis, length=1.0, width=0.6)
    robot = at(rect, x, y)
    if abs(x) < 0.5 + 0.05 and abs(y) < 0.3 + 0.05:
        return
    step = choose(rect, robot, far_side(rect), MARGIN, GAP, seen)
    seen = [p for p in seen if math.dist(p, robot) < AHEAD]  # the rest is read later, from nearer
    if step.stop:
        ahead = [p for p in seen if in_way(p, robot, step.points[0], CLEAR)]
        assert all(math.dist(robot, p) < CLEAR or math.dist(step.points[0], p) >= CLEAR - 1e-6 for p in ahead)
    else:
        assert first_block(robot, step.points, seen, CLEAR) is None
        assert local(rect, step.points)[-1] == (0.0, 0.65)


def test_things_beyond_ahead_are_left_out_and_a_kept_end_is_the_only_one() -> None:
    robot = at(TABLE, 0.3, -1.2)
    far = at(TABLE, 1.1, 0.8)  # on the near end's second corner, 2 m away: read later, from nearer
    assert local(TABLE, choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, [far]).points)[0][0] > 0
    waiting = at(TABLE, 1.0, -0.85)
    kept = choose(TABLE, robot, far_side(TABLE), MARGIN, GAP, [waiting], keep=1.0)
    assert all(x >= 0 for x, _ in local(TABLE, kept.points))
