"""What lies in the way of a move, by the humanoid's range finder (hfsm_behaviours.drive.things): a
thing sensed ahead along the move's heading, within a lane as wide as two bodies. The paper's
approach and search moves, blind in its two-robot runs, use it in a room (a table named)."""

from __future__ import annotations

import math
from collections.abc import Callable

from hfsm.primitive import Context
from hfsm_behaviours.drive.things import BEAMS, things

Point = tuple[float, float]
LANE = 0.4  # metres either side of a move's line within which a thing sensed is in its way
WARY = 0.6  # metres ahead an approach move looks in a room


def blocks(seen: list[Point], look: float) -> bool:
    """Whether a thing `seen` ((forward, left) m, body frame) lies in the way ahead within `look` m."""
    return any(0.0 < f < look and abs(left) < LANE for f, left in seen)


def turned(seen: list[Point], turn: float) -> list[Point]:
    """`seen` in the frame of a heading `turn` rad (left +) from the body's."""
    c, s = math.cos(turn), math.sin(turn)
    return [(c * f + s * left, -s * f + c * left) for f, left in seen]


def sensed(ctx: Context, look: float) -> list[Point]:
    """The things the range finder sees within a little more than `look` m (body frame)."""
    return things(ctx.robot.scan(BEAMS, look + 0.5), look + 0.4)


def in_way(ctx: Context, look: float) -> Callable[[float], bool]:
    """For hfsm_behaviours.body.Body's `blocked`: is a thing in the way of a move at this heading
    (rad, body frame, left +) within `look` m?"""
    return lambda heading: blocks(turned(sensed(ctx, look), heading), look)
