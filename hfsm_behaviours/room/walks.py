"""Walks to a table across the room: where to stand, the way there, and who goes first.

A robot sent to a table it does not stand at (a helper, a spare, a robot lent after its own table)
walks to a *place* beside that table: the middle of one of its long sides, `GAP` m from its centre
line, as the pairs start (the side with the fewest robots near it, then the nearer one). The way
there is a shortest path on a grid of the room (networkx A*) that keeps `BODY` m off the walls,
`BODY` m off every table's top, `KEEP` m off every robot known to stand still (where it last said it
was: failed robots, waiting spares, pairs at work), and costs `CORRIDOR` times more inside a table's
claimed carry corridor (a pair may carry through it). It is then shortened where a straight line
stays as clear. Where no way keeps `KEEP` m off the robots, one keeping `TIGHT` m is taken; where
none does either (a robot hemmed in by a table, a wall and robots standing at work), the walker has
no way yet and waits for the others to move (machines/room_carry.yaml's `boxed`), never walking
straight through them.

Right of way: a walker says its path and, as it walks, where it is; two walkers whose paths come
within `2 * HALF` m of each other do not walk at once: the one that said its walk first (then the
one with fewer robots standing in its way, then the smaller id) goes, the other waits while what is
left of the first one's way (`left_of`, from where it said it is) still comes that near the first
`HEAD` m of its own (`head`: beyond, it would meet the first one only behind it or after it passed,
and both sense each other), or until the first stops saying it (arrived), for a bounded time.

Everything here is pure and in the room's frame.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import networkx as nx

from hfsm_behaviours.room.claims import GAP, Rect, places, way
from hfsm_behaviours.room.frames import at_wall

Point = tuple[float, float]
CELL = 0.25  # metres between grid nodes
BODY = 0.4  # metres from a walker's centre to a wall or a table's top, at least
KEEP = 0.8  # metres from a walker's centre to a robot standing still, at least
TIGHT = 0.6  # the same where no way keeps KEEP: a body's width and a little, never less
CORRIDOR = 4.0  # a metre walked in a claimed corridor costs this many
HALF = 0.45  # half the width of the strip a walker sweeps
WALL = 0.35  # metres from a wall within which no robot stands
HEAD = 2.0  # metres of its way a walker about to set off keeps clear of an earlier walker's


@dataclass(frozen=True)
class Scene:
    """What a walker avoids: the room (centred on 0), tables' tops, claimed corridors, robots."""

    width: float
    depth: float
    tables: tuple[Rect, ...] = ()
    corridors: tuple[Rect, ...] = ()
    robots: tuple[Point, ...] = ()
    keep: float = KEEP

    def blocked(self, p: Point) -> bool:
        if abs(p[0]) > self.width / 2 - BODY or abs(p[1]) > self.depth / 2 - BODY:
            return True
        if any(t.contains(p, BODY) for t in self.tables):
            return True
        return any(math.dist(p, r) < self.keep for r in self.robots)

    def in_corridor(self, p: Point, margin: float = 0.0) -> bool:
        return any(c.contains(p, margin) for c in self.corridors)


def table_where(table: Mapping[str, Any], done: bool, seen: Sequence[float] | None) -> Point:
    """Where a table is believed to stand: at its wall when done, where a survivor saw it, else its start."""
    if done:
        x, y = at_wall(table)
        return (x, y)
    if seen is not None:
        return (float(seen[0]), float(seen[1]))
    return (float(table["x"]), float(table["y"]))


def corridor(table: Mapping[str, Any], width: float, depth: float, reach: float = 0.5) -> Rect:
    """The claimed corridor of a table (claims.way, the sign that heads for its `toward`)."""
    yaw = math.radians(float(table.get("yaw", 0.0)))
    tx, ty = float(table["toward"][0]) - float(table["x"]), float(table["toward"][1]) - float(table["y"])
    sign = 1 if tx * math.cos(yaw) + ty * math.sin(yaw) >= 0 else -1
    return way(table, sign, width, depth, reach).corridor


def place_for(table: Mapping[str, Any], at: Point, me: Point, others: Sequence[Point],
              gap: float = GAP, partner: Point | None = None, leads: bool = True,
              room: tuple[float, float] | None = None, tops: Sequence[Rect] = ()) -> Point:
    """Of the two places beside the table, the one with fewer robots within `KEEP` m of it (a failed
    robot stands at the other), then the nearer one to `me`. With a `partner` (where it said it
    stands), the pair takes one place each, the way that puts both nearer their places (a partner
    standing at one keeps it); when both ways are as near, the pair's leader (`leads`: this robot,
    else the partner) takes the place the rule above gives it and the other robot the other place:
    two robots walking to one table never head for the same side. A place no robot can stand at
    (within `WALL` m of a wall of the `room`, {width, depth} centred on the origin, or beyond it), or
    within `BODY` m of another table's top (`tops`, where they stand: walking there pushes that
    table), is not taken while the other is: the robot alone or the pair's leader takes the free
    place and the assistant (`leads` false) heads for the free side's end nearer to it (`beyond`),
    from where the paper's assistant walks round to its side, rather than for its leader's place
    (the second to arrive would find the first standing there and walk about it)."""
    sides = places(table, at, gap)

    def standing(p: Point) -> bool:
        return (room is None or standable(p, room)) and not any(t.contains(p, BODY) for t in tops)
    free = [p for p in sides if standing(p)]
    if len(free) == 1:
        if partner is None or leads:
            return free[0]
        ends = [p for p in beyond(table, at, free[0]) if standing(p)]
        return min(ends, key=lambda p: (math.dist(p, me), p)) if ends else free[0]

    def key(p: Point, who: Point) -> tuple[int, float]:
        return (sum(math.dist(p, o) < KEEP for o in others if o != partner), math.dist(p, who))
    if partner is None:
        return min(sides, key=lambda p: key(p, me))
    first = math.dist(me, sides[0]) + math.dist(partner, sides[1])
    second = math.dist(me, sides[1]) + math.dist(partner, sides[0])
    if abs(first - second) > 1e-6:
        return sides[0] if first < second else sides[1]
    theirs = min(sides, key=lambda p: key(p, me if leads else partner))
    if leads:
        return theirs
    return sides[1] if theirs == sides[0] else sides[0]


def beyond(table: Mapping[str, Any], at: Point, place: Point, out: float = 0.6) -> list[Point]:
    """The two points `out` m past the table's ends along its long axis, `out` m from its centre line
    on the side of `place`."""
    yaw = math.radians(float(table.get("yaw", 0.0)))
    ux, uy = math.cos(yaw), math.sin(yaw)
    side = 1.0 if -uy * (place[0] - at[0]) + ux * (place[1] - at[1]) >= 0 else -1.0
    along = float(table.get("length", 0.8)) / 2 + out
    return [(at[0] + end * along * ux - side * out * uy, at[1] + end * along * uy + side * out * ux)
            for end in (1.0, -1.0)]


def standable(p: Point, room: tuple[float, float], wall: float = WALL) -> bool:
    """Whether a robot can stand at `p` in a room of (width, depth) centred on the origin."""
    return abs(p[0]) <= room[0] / 2 - wall and abs(p[1]) <= room[1] / 2 - wall


def _node(p: Point, scene: Scene) -> tuple[int, int]:
    return (round((p[0] + scene.width / 2) / CELL), round((p[1] + scene.depth / 2) / CELL))


def _point(n: tuple[int, int], scene: Scene) -> Point:
    return (n[0] * CELL - scene.width / 2, n[1] * CELL - scene.depth / 2)


def grid(scene: Scene) -> Any:
    """The free grid nodes, 8-connected, each edge weighted by its length (times CORRIDOR inside a
    corridor)."""
    g = nx.Graph()
    cols, rows = int(scene.width / CELL) + 1, int(scene.depth / CELL) + 1
    free = {(i, j) for i in range(cols) for j in range(rows) if not scene.blocked(_point((i, j), scene))}
    for i, j in sorted(free):
        for di, dj in ((1, 0), (0, 1), (1, 1), (1, -1)):
            other = (i + di, j + dj)
            if other not in free:
                continue
            a, b = _point((i, j), scene), _point(other, scene)
            mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            g.add_edge((i, j), other, weight=math.dist(a, b) * (CORRIDOR if scene.in_corridor(mid) else 1.0))
    return g


def samples(a: Point, b: Point, step: float = 0.1) -> list[Point]:
    """Points along the straight line from a to b, both ends included, at most `step` m apart."""
    n = max(1, math.ceil(math.dist(a, b) / step))
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n + 1)]


def _cost(points: Sequence[Point], scene: Scene) -> float:
    total = 0.0
    for a, b in itertools.pairwise(points):
        for p, q in itertools.pairwise(samples(a, b)):
            mid = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
            total += math.dist(p, q) * (CORRIDOR if scene.in_corridor(mid) else 1.0)
    return total


def shorten(path: Sequence[Point], scene: Scene) -> list[Point]:
    """The path with each stretch replaced by a straight line where that line stays clear and costs
    no more (string pulling)."""
    if len(path) <= 2:
        return list(path)
    out, i = [path[0]], 0
    while i < len(path) - 1:
        j = len(path) - 1
        while j > i + 1:
            line = samples(path[i], path[j])
            if (not any(scene.blocked(p) for p in line[1:-1])
                    and _cost([path[i], path[j]], scene) <= _cost(path[i:j + 1], scene) + 1e-6):
                break
            j -= 1
        out.append(path[j])
        i = j
    return out


def plan_walk(scene: Scene, start: Point, goal: Point) -> list[Point] | None:
    """Waypoints from `start` to `goal` (the first after the start, the goal last), or None when no
    way is free. A start or goal inside a blocked zone leaves it by its nearest free node."""
    g = grid(scene)
    if g.number_of_nodes() == 0:
        return None

    def nearest(p: Point) -> tuple[int, int]:
        n = _node(p, scene)
        if n in g:
            return n
        best: tuple[int, int] = min(g.nodes, key=lambda m: (math.dist(_point(m, scene), p), m))
        return best

    a, b = nearest(start), nearest(goal)
    try:
        nodes = nx.astar_path(g, a, b, heuristic=lambda u, v: math.dist(_point(u, scene), _point(v, scene)),
                              weight="weight")
    except nx.NetworkXNoPath:
        return None
    points = [start, *(_point(n, scene) for n in nodes[1:-1]), goal]
    return [(round(x, 4), round(y, 4)) for x, y in shorten(points, scene)[1:]]


def way_to(scene: Scene, start: Point, goal: Point, wait: bool) -> list[Point] | None:
    """The way from `start` to `goal`: one keeping `scene.keep` m off the robots standing, else one
    keeping `TIGHT` m; where neither is free, None when the walker may wait for them to move (`wait`),
    else a way round the walls, tables and corridors alone (the robots standing on it are sensed and
    stepped round as it walks), the straight line only where even that is closed."""
    points = plan_walk(scene, start, goal) or plan_walk(replace(scene, keep=TIGHT), start, goal)
    if points is not None or wait:
        return points
    return plan_walk(replace(scene, robots=()), start, goal) or [goal]


def _segment_gap(a: Point, b: Point, c: Point, d: Point) -> float:
    """The least distance between segments ab and cd."""
    def to_segment(p: Point, s: Point, e: Point) -> float:
        vx, vy = e[0] - s[0], e[1] - s[1]
        length2 = vx * vx + vy * vy
        t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - s[0]) * vx + (p[1] - s[1]) * vy) / length2))
        return math.dist(p, (s[0] + t * vx, s[1] + t * vy))

    def crosses() -> bool:
        def side(p: Point, q: Point, r: Point) -> float:
            return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
        return side(a, b, c) * side(a, b, d) < 0 and side(c, d, a) * side(c, d, b) < 0

    if crosses():
        return 0.0
    return min(to_segment(a, c, d), to_segment(b, c, d), to_segment(c, a, b), to_segment(d, a, b))


def conflict(mine: Sequence[Point], theirs: Sequence[Point], half: float = HALF) -> bool:
    """Whether two walks (each its start then its waypoints) sweep strips `half` m wide each side
    that meet."""
    ours = list(itertools.pairwise(mine)) or [(mine[0], mine[0])]
    other = list(itertools.pairwise(theirs)) or [(theirs[0], theirs[0])]
    return any(_segment_gap(a, b, c, d) < 2 * half for a, b in ours for c, d in other)


def goes_first(mine: tuple[float, int, str], theirs: tuple[float, int, str]) -> bool:
    """Right of way between two walkers: (when each said its walk first, how many robots stand in its
    way (`crowd`: in a packed start, those on the outside get out first), its id); the smaller goes."""
    return (round(mine[0], 6), mine[1], mine[2]) < (round(theirs[0], 6), theirs[1], theirs[2])


def crowd(walk: Sequence[Point], standing: Sequence[Point], half: float = HALF) -> int:
    """How many of the robots `standing` a walk (its start then its waypoints) passes within `half` m
    of: robots in its way, not those beside it (parked 0.8 m apart, a neighbour is not in the way)."""
    return sum(conflict(walk, [p], half / 2) for p in standing)


def left_of(path: Sequence[Point], at: Point) -> list[Point]:
    """What is left of a walk (its start then its waypoints) for a walker at `at`: `at`, then the
    waypoints after the stretch of the walk nearest it."""
    if len(path) < 2:
        return [at]
    stretches = list(itertools.pairwise(path))
    nearest = min(range(len(stretches)), key=lambda k: _segment_gap(at, at, *stretches[k]))
    return [at, *path[nearest + 1:]]


def head(path: Sequence[Point], metres: float = HEAD) -> list[Point]:
    """The first `metres` of a walk (its start then its waypoints)."""
    out, left = [path[0]], metres
    for a, b in itertools.pairwise(path):
        step = math.dist(a, b)
        if step >= left:
            t = left / step if step > 0 else 0.0
            out.append((a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t))
            return out
        out.append(b)
        left -= step
    return out
