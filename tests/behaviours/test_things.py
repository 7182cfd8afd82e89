"""A humanoid's range finder read for things (hfsm_behaviours/drive/things.py), world-free: scans cast
by hand in a room with robots (discs) in it."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st
from scans import cast

from hfsm_behaviours.drive.avoid import SCAN_EVERY, Sensing, sensed
from hfsm_behaviours.drive.things import BEAMS, things

LOOK = 1.2


def near(seen: list[tuple[float, float]], within: float = 1.0) -> list[tuple[float, float]]:
    return [q for q in seen if math.hypot(*q) < within]


def test_a_wall_alone_is_no_thing() -> None:
    """(At the edge of `look`, where beams graze a wall far apart, a stray end may count as a thing:
    beyond any clearance, it only brakes a walk coming straight at it.)"""
    assert near(things(cast((5.5, 0.0, 0.3), BEAMS, LOOK + 0.1), LOOK)) == []  # 0.5 m from the wall x = 6
    assert near(things(cast((5.6, 4.1, 0.0), BEAMS, LOOK + 0.1), LOOK)) == []  # in a corner


def test_a_robot_ahead_is_seen_at_its_nearest_point() -> None:
    seen = things(cast((0.0, 0.0, 0.0), BEAMS, LOOK + 0.1, clutter=((0.8, 0.0, 0.15),)), LOOK)
    assert len(seen) == 1 and seen[0] == pytest.approx((0.65, 0.0), abs=0.02)


def test_a_robot_against_a_wall_is_seen() -> None:
    seen = things(cast((5.0, 0.0, 0.0), BEAMS, LOOK + 0.1, clutter=((5.8, 0.0, 0.15),)), LOOK)
    assert seen and min(math.hypot(*q) for q in seen) == pytest.approx(0.65, abs=0.03)


def test_robots_shoulder_to_shoulder_are_seen() -> None:
    crowd = tuple((0.7, y, 0.15) for y in (-0.3, 0.0, 0.3))
    seen = things(cast((0.0, 0.0, 0.0), BEAMS, LOOK + 0.1, clutter=crowd), LOOK)
    assert seen and seen[0] == pytest.approx((0.55, 0.0), abs=0.03)


@given(st.floats(0.35, 1.0), st.floats(-math.pi, math.pi), st.floats(-math.pi, math.pi))
def test_a_robot_within_look_is_always_seen(gap: float, bearing: float, yaw: float) -> None:
    clutter = ((gap * math.cos(bearing), gap * math.sin(bearing), 0.15),)
    seen = things(cast((0.0, 0.0, yaw), BEAMS, LOOK + 0.1, clutter=clutter), LOOK)
    assert any(math.hypot(*q) < gap - 0.1 for q in seen)


class Scanning:
    def scan(self, beams: int, reach: float) -> list[float]:
        return cast((0.0, 0.0, math.pi / 2), beams, reach, clutter=((0.0, 0.8, 0.15),))


def test_sensed_turns_what_a_range_finder_sees_into_the_odometry_frame() -> None:
    seen = sensed(Scanning(), LOOK, math.pi / 2)
    assert len(seen) == 1 and seen[0] == pytest.approx((0.0, 0.65), abs=0.02)
    assert sensed(Scanning(), 0.0, 0.0) == []


class Counting(Scanning):
    scans = 0

    def scan(self, beams: int, reach: float) -> list[float]:
        self.scans += 1
        return super().scan(beams, reach)


def test_a_range_finder_scans_every_quarter_second_and_keeps_what_it_saw_where_it_was() -> None:
    robot = Counting()
    sensing = Sensing(robot, LOOK)
    first = sensing.seen(0.0, (0.0, 0.0, math.pi / 2))
    moved = sensing.seen(0.2, (0.0, 0.3, math.pi / 2))  # walked 0.3 m towards it: no new scan
    assert robot.scans == 1
    assert moved[0] == pytest.approx((first[0][0], first[0][1] - 0.3))
    sensing.seen(SCAN_EVERY, (0.0, 0.3, math.pi / 2))
    assert robot.scans == 2


def test_a_random_walk_turns_from_what_is_in_its_way() -> None:
    from hfsm_behaviours.approach.search import _turned, blocks

    ahead = [(0.5, 0.1)]  # a robot's side 0.5 m ahead
    assert blocks(ahead, 0.8)
    assert not blocks(ahead, 0.4)  # beyond the look
    assert not blocks([(0.5, 0.6)], 0.8)  # beside the way
    assert not blocks([(-0.5, 0.0)], 0.8)  # behind
    # turned a quarter left, the robot ahead is on its right, out of the way
    assert _turned(ahead, math.pi / 2)[0] == pytest.approx((0.1, -0.5))
    assert not blocks(_turned(ahead, math.pi / 2), 0.8)
