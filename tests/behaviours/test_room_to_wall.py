"""table_at_wall's geometry: how far the table's end can move along the carry before a corner
meets the wall line, for square and oblique walls."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.carry.wall import room_to_wall
from hfsm_sim.perception import WallSeen


def wall_at(distance: float, normal_deg: float) -> WallSeen:
    return WallSeen(True, distance=distance, points=20, normal=math.radians(normal_deg))


@given(st.floats(0.5, 3.0), st.floats(0.1, 0.45), st.sampled_from([1.0, -1.0]))
def test_a_square_wall_is_its_distance_less_the_reach(distance: float, reach: float, sign: float) -> None:
    seen = wall_at(distance, 90.0 * sign)
    corners = [(0.09, sign * reach), (0.59, sign * reach)]
    assert room_to_wall(seen, corners, sign) == pytest.approx(distance - reach)


def test_an_oblique_wall_is_met_first_by_the_nearer_corner() -> None:
    # To the left, turned 20 degrees so that it leans towards the far edge (normal 70 degrees).
    seen = wall_at(1.0, 70.0)
    near, far = (0.09, 0.4), (0.59, 0.4)
    n = (math.cos(math.radians(70)), math.sin(math.radians(70)))
    along = [(1.0 - n[0] * x - n[1] * y) / n[1] for x, y in (near, far)]
    assert room_to_wall(seen, [near, far], 1.0) == pytest.approx(min(along))
    assert min(along) == pytest.approx(along[1]) and along[1] < 1.0 - 0.4  # shorter than square
    assert room_to_wall(seen, [near], 1.0) > room_to_wall(seen, [near, far], 1.0)  # width counts


@pytest.mark.parametrize("normal", [0.0, 180.0, 10.0, -90.0])
def test_a_wall_along_the_carry_or_behind_it_cannot_be_judged(normal: float) -> None:
    assert room_to_wall(wall_at(1.0, normal), [(0.09, 0.4)], 1.0) == math.inf
