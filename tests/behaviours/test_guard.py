"""The safety guard under every humanoid motion (hfsm_behaviours/drive/guard.py), world-free: what it
lets through for things in the way, beside it and behind it, and a fake body commanded through it."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.drive.avoid import tops_near
from hfsm_behaviours.drive.guard import LANE, SLOW, STOP, TURN_STOP, Guarded, let_through

WALK = (0.1, 0.0, 0.0)
CRAB_LEFT = (0.0, 0.1, 0.0)


def test_nothing_seen_lets_all_through() -> None:
    assert let_through(WALK, [], holding=False) == 1.0
    assert let_through((0.0, 0.0, 0.5), [], holding=False) == 1.0


def test_a_thing_ahead_slows_then_stops_the_walk() -> None:
    assert let_through(WALK, [(SLOW + 0.05, 0.0)], holding=False) == 1.0
    middle = let_through(WALK, [((SLOW + STOP) / 2, 0.0)], holding=False)
    assert 0.4 < middle < 0.6
    assert let_through(WALK, [(STOP, 0.0)], holding=False) == 0.0
    assert let_through(WALK, [(STOP - 0.05, 0.1)], holding=False) == 0.0


def test_a_thing_beside_or_behind_never_holds_a_walk_back() -> None:
    assert let_through(WALK, [(0.1, LANE + 0.05)], holding=False) == 1.0
    assert let_through(WALK, [(-0.2, 0.0)], holding=False) == 1.0
    backwards = (-0.1, 0.0, 0.0)
    assert let_through(backwards, [(0.2, 0.0)], holding=False) == 1.0
    assert let_through(backwards, [(-0.2, 0.0)], holding=False) == 0.0


def test_the_direction_of_motion_is_what_counts() -> None:
    """A crab to the left stops for a thing on its left, not for one ahead."""
    assert let_through(CRAB_LEFT, [(0.0, 0.25)], holding=False) == 0.0
    assert let_through(CRAB_LEFT, [(0.45, 0.0)], holding=False) == 1.0


def test_holding_a_table_leaves_out_what_lies_in_front() -> None:
    """A carry's own table legs and partner lie in front; a robot beside still stops it."""
    legs = [(0.12, 0.3), (0.6, 0.3), (0.12, -0.3)]
    assert let_through(CRAB_LEFT, legs, holding=True) == 1.0
    assert let_through(CRAB_LEFT, legs, holding=False) == 0.0
    assert let_through(CRAB_LEFT, [(-0.05, 0.25)], holding=True) == 0.0


def test_a_turn_on_the_spot_stops_only_for_a_thing_at_its_corners() -> None:
    assert let_through((0.0, 0.0, 0.5), [(TURN_STOP + 0.05, 0.0)], holding=False) == 1.0
    assert let_through((0.0, 0.0, 0.5), [(TURN_STOP - 0.03, 0.0)], holding=False) == 0.0


@given(st.floats(-math.pi, math.pi), st.floats(0.17, 2.0), st.floats(-math.pi, math.pi))
def test_never_lets_a_walk_close_on_a_thing_within_stop(heading: float, gap: float, bearing: float) -> None:
    """Whatever the motion and wherever the thing: if the thing is within STOP and the way, moving
    leads nearer to it only at speed 0; the fraction is always within 0-1."""
    velocity = (0.1 * math.cos(heading), 0.1 * math.sin(heading), 0.0)
    thing = (gap * math.cos(bearing), gap * math.sin(bearing))
    fraction = let_through(velocity, [thing], holding=False)
    assert 0.0 <= fraction <= 1.0
    along = thing[0] * math.cos(heading) + thing[1] * math.sin(heading)
    lateral = abs(thing[0] * math.sin(heading) - thing[1] * math.cos(heading))
    if along > 0 and lateral <= LANE and along <= STOP:
        assert fraction == 0.0
    if along <= 0:
        assert fraction == 1.0


@dataclass
class FakeBody:
    """A body whose range finder sees one thing `ahead` metres straight ahead (its scan, beam 0)."""

    ahead: float
    failed: bool = False
    commanded: list[tuple[float, float, float]] = field(default_factory=list)

    def set_velocity(self, forward: float, sideways: float, turn: float) -> None:
        self.commanded.append((forward, sideways, turn))

    def velocity(self) -> tuple[float, float, float]:
        return self.commanded[-1] if self.commanded else (0.0, 0.0, 0.0)

    def odometry(self) -> tuple[float, float, float]:
        return (0.0, 0.0, 0.0)

    def holding(self) -> bool:
        return False

    def scan(self, beams: int, reach: float) -> list[float]:
        width = 0.15  # a robot's side: beams within its half-width hit it
        out = []
        for k in range(beams):
            angle = 2 * math.pi * k / beams
            hit = self.ahead / math.cos(angle) if math.cos(angle) > 0 else math.inf
            out.append(hit if abs(hit * math.sin(angle)) <= width and hit < reach else reach)
        return out


def test_a_guarded_body_is_stopped_until_the_way_clears() -> None:
    body = FakeBody(ahead=0.25)
    guarded = Guarded(body)
    guarded.set_velocity(0.1, 0.0, 0.0)
    assert body.commanded[-1] == (0.1, 0.0, 0.0)  # not yet judged
    for k in range(10):
        guarded.update(k * 0.05, 0.05)
    assert body.commanded[-1] == (0.0, 0.0, 0.0)
    assert guarded.passed == 0.0 and math.isclose(guarded.held, 0.5)
    body.ahead = 5.0  # it walked off
    for k in range(10, 16):
        guarded.update(k * 0.05, 0.05)
    assert body.commanded[-1] == (0.1, 0.0, 0.0)
    assert guarded.passed == 1.0 and guarded.held == 0.0


def test_a_stopped_body_is_not_judged() -> None:
    body = FakeBody(ahead=0.25)
    guarded = Guarded(body)
    guarded.stop()
    guarded.update(0.0, 0.05)
    assert guarded.passed == 1.0 and guarded.held == 0.0


def test_a_table_top_below_the_beams_is_kept_off_as_a_thing() -> None:
    """go_along's `tops`: the nearest point of a table the team believes stands there, relative to
    the robot; none beyond `look`; a belief that puts the robot inside the top gives its nearest edge."""
    top = [1.0, 0.0, 0.0, 0.8, 0.5]  # x 0.6-1.4, y -0.25-0.25
    assert tops_near((0.0, 0.0, 0.0), [top], 1.2) == [(0.6, 0.0)]
    assert tops_near((1.0, 1.0, 0.0), [top], 1.2) == [(0.0, -0.75)]
    assert tops_near((0.0, 3.0, 0.0), [top], 1.2) == []
    inside = tops_near((1.3, 0.0, 0.0), [top], 1.2)
    assert len(inside) == 1 and inside[0] == pytest.approx((0.1, 0.0))
    turned = tops_near((1.0, 1.0, 0.0), [[1.0, 0.0, math.pi / 2, 0.8, 0.5]], 1.2)
    assert turned[0] == pytest.approx((0.0, -0.6))
