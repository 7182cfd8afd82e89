"""Which way round the table the assistant walks, from what its range finder senses (pure).

`go_to_opposite_side_of_table` walks round its table's corners to the long side across from its
leader. Blind, it took the corner on its own half of the table, whoever stood on the way. Here both
ways round are laid out (`ways`), each leg is checked against the things sensed near it (robots:
`hfsm_behaviours.drive.things`; a table on the floor is below the beams), and the way with no thing
within `clear` of its legs is taken, the shorter if both are free. When neither is free, a point
beside the first thing in the way (away from the table) is tried as a step round it; when no step
round is free either, the walk stops `clear` short of that thing (`Step.stop`), to look again.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from hfsm_behaviours.approach.frames import Point, Side, from_table_frame, table_frame
from hfsm_sim.perception.table_rect import TableRect

CLEAR = 0.45  # metres from a leg's line to the nearest point sensed of a thing for the leg to be free
AHEAD = 1.2  # metres from the walker within which a thing sensed is taken into account (beyond, a
#              wall's end clipped by the range or cut by robots before it reads as a thing)


@dataclass(frozen=True)
class Step:
    """The legs to walk (odometry frame); `stop`: none is free, walk only the first (short of a thing)."""

    points: list[Point]
    stop: bool = False


def route(rect: TableRect, robot: Point, target: Side, margin: float, gap: float,
          way: float = 0.0) -> list[Point]:
    """Waypoints to `gap` out from the target side's middle, round the corners `margin` out,
    never along the other long side's middle. `way` (+1 or -1: the end of the table, along its
    axis, to go round; 0: the end on the robot's own half)."""
    x, y = table_frame(rect, robot)
    t = 1.0 if table_frame(rect, target.middle)[1] >= 0 else -1.0
    half_l, half_w = rect.length / 2, rect.width / 2
    sx = way if way != 0.0 else (1.0 if x >= 0 else -1.0)
    points: list[Point] = []
    if y * t < half_w + gap / 2:
        if y * t < -half_w or (x * sx < 0 and abs(x) > half_l):
            if x * sx < 0 and abs(x) > half_l and y * t >= -half_w:
                points.append((-sx * (half_l + margin), -t * (half_w + margin)))
            points.append((sx * (half_l + margin), -t * (half_w + margin)))
        points.append((sx * (half_l + margin), t * (half_w + margin)))
    points.append((0.0, t * (half_w + gap)))
    return [from_table_frame(rect, p) for p in points]


def in_way(p: Point, a: Point, b: Point, clear: float) -> bool:
    """Whether `p` lies within `clear` of the leg a-b, not behind its start (a thing beside or
    behind the walker is walked away from)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    norm = dx * dx + dy * dy
    k = 0.0 if norm < 1e-12 else ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / norm
    if k < 0.0:
        return False
    k = min(1.0, k)
    return math.hypot(p[0] - a[0] - k * dx, p[1] - a[1] - k * dy) < clear


def length(robot: Point, points: list[Point]) -> float:
    return sum(math.dist(a, b) for a, b in itertools.pairwise([robot, *points]))


def first_block(robot: Point, points: list[Point], seen: list[Point],
                clear: float) -> tuple[int, Point] | None:
    """The first leg (index into `points`) with a thing sensed in its way, and that thing (the one
    nearest the leg's start); None when every leg is free."""
    for k, (a, b) in enumerate(itertools.pairwise([robot, *points])):
        near = [p for p in seen if in_way(p, a, b, clear)]
        if near:
            return k, min(near, key=lambda p: math.dist(p, a))
    return None


def inside(rect: TableRect, p: Point, margin: float) -> bool:
    """Whether `p` lies within `margin` of the table's top."""
    x, y = table_frame(rect, p)
    return abs(x) < rect.length / 2 + margin and abs(y) < rect.width / 2 + margin


def crosses(rect: TableRect, a: Point, b: Point, margin: float) -> bool:
    """Whether the segment a-b passes within `margin` of the table's top (sampled every 5 cm)."""
    n = max(1, math.ceil(math.dist(a, b) / 0.05))
    return any(inside(rect, (a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n), margin)
               for i in range(n + 1))


def round_thing(rect: TableRect, robot: Point, points: list[Point], k: int, thing: Point,
                seen: list[Point], clear: float, margin: float) -> list[Point] | None:
    """`points` with a step round `thing` (in the way of leg `k`) put before that leg's end, on the
    thing's side away from the table first; None when no such step leaves every leg free."""
    start = robot if k == 0 else points[k - 1]
    dx, dy = points[k][0] - start[0], points[k][1] - start[1]
    norm = math.hypot(dx, dy) or 1.0
    across = (-dy / norm, dx / norm)
    away = (thing[0] - rect.x, thing[1] - rect.y)
    for s in sorted((1.0, -1.0), key=lambda s: -s * (across[0] * away[0] + across[1] * away[1])):
        for reach in (clear + 0.1, clear + 0.4):
            step = (thing[0] + s * across[0] * reach, thing[1] + s * across[1] * reach)
            legs = [*points[:k], step, *points[k:]]
            if inside(rect, step, margin * 0.8) or crosses(rect, start, step, 0.2) \
                    or crosses(rect, step, points[k], 0.2):
                continue
            if first_block(robot, legs, seen, clear) is None:
                return legs
    return None


def own_way(rect: TableRect, robot: Point) -> float:
    """The end of the table on the robot's own half (+1 or -1 along the axis)."""
    return 1.0 if table_frame(rect, robot)[0] >= 0 else -1.0


def choose(rect: TableRect, robot: Point, target: Side, margin: float, gap: float,
           seen: list[Point], clear: float = CLEAR, keep: float = 0.0) -> Step:
    """The way round to walk from `robot`, given the things `seen` (odometry frame) within AHEAD m:
    a free way (the shorter of two), else a free step round the first thing in the way, else a stop
    short. `keep` (+1 or -1): only that end of the table is gone round (a walker that has changed its
    way too often)."""
    seen = [p for p in seen if math.dist(p, robot) < AHEAD]
    own = route(rect, robot, target, margin, gap, way=keep)
    other = route(rect, robot, target, margin, gap, way=-own_way(rect, robot))
    alone = other == own or keep != 0.0
    candidates = [own] if alone else sorted((own, other), key=lambda pts: length(robot, pts))
    blocks = [first_block(robot, pts, seen, clear) for pts in candidates]
    for pts, block in zip(candidates, blocks, strict=True):
        if block is None:
            return Step(pts)
    for pts, block in zip(candidates, blocks, strict=True):
        assert block is not None
        stepped = round_thing(rect, robot, pts, block[0], block[1], seen, clear, margin)
        if stepped is not None:
            return Step(stepped)
    return Step([short_of(robot, candidates[0], seen, clear)], stop=True)


def short_of(robot: Point, points: list[Point], seen: list[Point], clear: float) -> Point:
    """The point on the first leg where the walk must stop to stay `clear` off every thing sensed
    ahead: the robot itself when a thing is already that near."""
    a, b = robot, points[0]
    span = math.dist(a, b)
    if span < 1e-9:
        return a
    ux, uy = (b[0] - a[0]) / span, (b[1] - a[1]) / span
    stop = span
    for p in seen:
        along = (p[0] - a[0]) * ux + (p[1] - a[1]) * uy
        off = abs(-(p[0] - a[0]) * uy + (p[1] - a[1]) * ux)
        if off < clear and along >= 0.0:
            stop = min(stop, max(0.0, along - math.sqrt(clear * clear - off * off)))
    return (a[0] + ux * stop, a[1] + uy * stop)
