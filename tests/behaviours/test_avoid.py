"""Steering round what a robot senses: never towards a thing nearer than the clearance."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from behaviours.drive.avoid import Detour, dodge

coord = st.floats(-1.0, 1.0, allow_nan=False)
points = st.lists(st.tuples(coord, coord).filter(lambda p: math.hypot(*p) > 0.05), max_size=5)


@given(st.tuples(coord, coord), points)
def test_never_towards_a_near_thing_and_never_too_fast(velocity: tuple[float, float],
                                                        seen: list[tuple[float, float]]) -> None:
    vx, vy = dodge(velocity, seen, 0.3, 0.5)
    assert math.hypot(vx, vy) <= 0.5 + 1e-9
    for ox, oy in seen:
        gap = math.hypot(ox, oy)
        if gap < 0.3:
            assert (vx * ox + vy * oy) / gap <= 1e-6


def test_head_on_it_keeps_right() -> None:
    vx, vy = dodge((0.5, 0.0), [(0.2, 0.0)], 0.3, 0.5)
    assert vx <= 1e-9 and vy < 0  # to the right of the way it was going (+x)


def test_wedged_it_takes_a_detour_across_its_way() -> None:
    detour = Detour()
    boxed = [(0.2, 0.0), (0.0, 0.2), (-0.2, 0.0), (0.0, -0.2)]
    got = [detour.steer(t * 0.05, (0.5, 0.0), boxed, 0.3, 0.5) for t in range(30)]
    assert all(math.hypot(*v) < 1e-9 for v in got)  # boxed in: it stays put
    assert detour.detours == 1 and abs(detour.way[0]) < 1e-9 and abs(detour.way[1]) == 0.5
