"""Steering round what a robot senses: never towards a thing nearer than the clearance."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.drive.avoid import CLOSING, Detour, brake, dodge
from hfsm_behaviours.drive.goto import heading

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


def _walk(detour: Detour | None, start: tuple[float, float], goal: tuple[float, float],
          posts: list[tuple[float, float]], seconds: float) -> tuple[float, float]:
    """A point robot (radius 0.15) driven as go_to drives, round posts of radius 0.15 it senses
    within 1 m (nearest points), at 0.5 m/s and 20 Hz; where it is after `seconds`."""
    from hfsm_behaviours.drive.goto import heading

    x, y = start
    for tick in range(round(seconds / 0.05)):
        left = math.dist((x, y), goal)
        if left < 0.1:
            break
        wanted = heading((x, y, 0.0), goal, 0.5, [], 0.3)
        seen = []
        for px, py in posts:
            gap = math.dist((x, y), (px, py))
            if gap - 0.3 < 1.0:
                seen.append(((px - x) * (gap - 0.3) / gap, (py - y) * (gap - 0.3) / gap))
        v = detour.steer(tick * 0.05, wanted, seen, 0.3, 0.5, left) if detour and seen else wanted
        x, y = x + v[0] * 0.05, y + v[1] * 0.05
    return (x, y)


def test_rocking_at_the_clearance_of_two_posts_before_its_goal_it_goes_round() -> None:
    """Two robots that failed stand south and east of it, its goal beyond them to the south-east:
    backing off and coming back in turn, it never crawls, so only its lack of progress tells it
    to go round (the bench's Figure 8 chain, its third allocation)."""
    posts = [(0.03, -0.44), (0.44, 0.08)]
    goal = (4.7, -3.4)
    end = _walk(Detour(), (0.0, 0.0), goal, posts, 60.0)
    assert math.dist(end, goal) < 0.1


@given(st.tuples(coord, coord), points)
def test_it_closes_on_what_it_senses_no_faster_than_it_can_stop_at_the_clearance(
        velocity: tuple[float, float], seen: list[tuple[float, float]]) -> None:
    one = [p for p in seen[:1] if math.hypot(*p) >= 0.3]
    vx, vy = brake(velocity, one, 0.3)
    assert math.hypot(vx, vy) <= math.hypot(*velocity) + 1e-9
    for ox, oy in one:
        gap = math.hypot(ox, oy)
        assert (vx * ox + vy * oy) / gap <= CLOSING * (gap - 0.3) + 1e-9


def test_two_robots_crossing_fast_never_touch() -> None:
    """Two round robots (radius 0.15) at 2 m/s, 20 Hz, each sensing the other's nearest point and
    driving as go_to drives, their bodies taking a few ticks to reach a new velocity (each tick 30 %
    of the last), their straight ways crossing at right angles (the bench's Figure 7 at 2.0 m/s):
    their centres stay more than 0.3 m apart; dodging only within the clearance, they touch."""
    def closest(brakes: bool) -> float:
        here = {"a": (-1.0, 0.0), "b": (0.0, -1.0)}
        goal = {"a": (1.0, 0.0), "b": (0.0, 1.0)}
        detours = {"a": Detour(), "b": Detour()}
        moving = {"a": (0.0, 0.0), "b": (0.0, 0.0)}
        nearest = math.inf
        for tick in range(60):
            step = {}
            for me, other in (("a", "b"), ("b", "a")):
                (x, y), (px, py) = here[me], here[other]
                wanted = heading((x, y, 0.0), goal[me], 2.0, [], 0.3)
                gap = math.dist((x, y), (px, py))
                seen = [((px - x) * (gap - 0.15) / gap, (py - y) * (gap - 0.15) / gap)] if gap - 0.15 < 1.0 else []
                if seen and not brakes:
                    seen = [p for p in seen if math.hypot(*p) < 0.3]  # as it was: only the clearance
                v = detours[me].steer(tick * 0.05, wanted, seen, 0.3, 2.0, math.dist((x, y), goal[me])) \
                    if seen else wanted
                v = moving[me] = (0.3 * moving[me][0] + 0.7 * v[0], 0.3 * moving[me][1] + 0.7 * v[1])
                step[me] = (x + v[0] * 0.05, y + v[1] * 0.05)
            here = step
            nearest = min(nearest, math.dist(here["a"], here["b"]))
        return nearest

    assert closest(brakes=True) > 0.3
    assert closest(brakes=False) < 0.3
