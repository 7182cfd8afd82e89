"""Rooms as users bring them, drawn from a seed: scenario mappings (and files) for `clear_room`.

A room is 6-16 m by 4-12 m; it holds 1-6 tables 0.6-1.5 m long and 0.4-0.9 m wide at any heading,
anywhere with at least 0.7 m between tables and 0.3 m between a table and a wall; 2K to 2K+4
humanoids (K tables, 16 at most) stand anywhere free, spread or packed as close as 0.8 m, facing
anywhere. Robots fail (none, one or two at any time, or at a rate up to 0.05 per robot per minute)
and the radio loses 0-30 % of messages, as the stratum says. Nothing here knows how the team clears
a room: a room is drawn only to be valid (`hfsm_sim.scenario`), never to be easy.

The strata (`STRATA`) name what a room stresses, so results can be read by kind.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

STRATA: dict[str, str] = {
    "open": "tables and robots anywhere, robots spread; no failure, lossless",
    "close": "two tables or more 0.7-1.0 m apart",
    "walls": "a table 0.3-0.6 m from a wall, or from two walls in a corner",
    "narrow": "a room 4-5 m across and 9-16 m long",
    "crowded": "the robots packed 0.8-1.0 m apart round one spot or corner",
    "failures": "one or two robots failing at any time (2-400 s), or a rate of 0.005-0.05 per robot "
                "per minute",
    "loss": "radio loss 5-30 %",
    "mixed": "each of the above drawn at random, together",
}
TIGHT = ("close", "walls", "narrow", "crowded")  # the "tight" strata
TABLE_GAP, WALL_GAP = 0.7, 0.3  # metres, at least: between tables, between a table and a wall
ROBOT_GAP = 0.8  # metres between robot centres, at least
ROBOT_WALL = 0.45  # a robot's centre from a wall (the scenario's 0.2 m, its 0.1 m jitter, and some)
ROBOT_TABLE = 0.5  # a robot's centre from a table's top
MAX_ROBOTS = 16  # hfsm_sim.scenario.MAX_FULL_ROBOTS
TRIES = 400

Point = tuple[float, float]


class NoRoom(Exception):
    """No valid room was drawn from this seed (it does not happen with the strata's ranges)."""


@dataclass(frozen=True)
class Table:
    x: float
    y: float
    yaw: float  # degrees
    length: float
    width: float

    def corners(self) -> list[Point]:
        c, s = math.cos(math.radians(self.yaw)), math.sin(math.radians(self.yaw))
        hl, hw = self.length / 2, self.width / 2
        return [(self.x + a * hl * c - b * hw * s, self.y + a * hl * s + b * hw * c)
                for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1))]

    def wall_gaps(self, width: float, depth: float) -> tuple[float, float, float, float]:
        """Distances from the top to the walls at +x, -x, +y, -y."""
        pts = self.corners()
        return (width / 2 - max(p[0] for p in pts), width / 2 + min(p[0] for p in pts),
                depth / 2 - max(p[1] for p in pts), depth / 2 + min(p[1] for p in pts))


def _segment_distance(p: Point, a: Point, b: Point) -> float:
    ax, ay = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / (ax * ax + ay * ay)))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay)


def _separated(a: Sequence[Point], b: Sequence[Point]) -> bool:
    """Whether a line separates the convex polygons (separating axes of both polygons' edges)."""
    for poly in (a, b):
        for i, p in enumerate(poly):
            q = poly[(i + 1) % len(poly)]
            nx, ny = q[1] - p[1], p[0] - q[0]
            pa = [nx * x + ny * y for x, y in a]
            pb = [nx * x + ny * y for x, y in b]
            if max(pa) < min(pb) or max(pb) < min(pa):
                return True
    return False


def polygon_gap(a: Sequence[Point], b: Sequence[Point]) -> float:
    """The distance between two convex polygons (0 when they overlap)."""
    if not _separated(a, b):
        return 0.0
    edges = [(p, q, r) for p, q in _edges(a) for r in b] + [(p, q, r) for p, q in _edges(b) for r in a]
    return min(_segment_distance(r, p, q) for p, q, r in edges)


def _edges(poly: Sequence[Point]) -> list[tuple[Point, Point]]:
    return [(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]


def point_gap(p: Point, poly: Sequence[Point]) -> float:
    """The distance from a point to a convex polygon's outline (0 inside it)."""
    if not _separated([p, (p[0] + 1e-9, p[1]), (p[0], p[1] + 1e-9)], poly):
        return 0.0
    return min(_segment_distance(p, a, b) for a, b in _edges(poly))


def _r(x: float, digits: int = 2) -> float:
    return round(x, digits)


def _size(rng: random.Random, narrow: bool) -> tuple[float, float]:
    if narrow:
        return _r(rng.uniform(9.0, 16.0), 1), _r(rng.uniform(4.0, 5.0), 1)
    return _r(rng.uniform(6.0, 16.0), 1), _r(rng.uniform(4.0, 12.0), 1)


def _fits(t: Table, tables: list[Table], width: float, depth: float) -> bool:
    if min(t.wall_gaps(width, depth)) < WALL_GAP:
        return False
    return all(polygon_gap(t.corners(), o.corners()) >= TABLE_GAP for o in tables)


def _table(rng: random.Random, width: float, depth: float, tables: list[Table], stratum: str) -> Table | None:
    length = _r(rng.uniform(0.6, 1.5))
    side = _r(rng.uniform(0.4, min(0.9, length)))
    yaw = float(rng.randrange(360))
    for _ in range(60):
        x, y = rng.uniform(-width / 2, width / 2), rng.uniform(-depth / 2, depth / 2)
        if stratum == "close" and tables:  # beside the last table, 0.7-1.0 m from its top
            last = tables[-1]
            angle, reach = rng.uniform(0, 2 * math.pi), rng.uniform(0.7, 1.0) + (length + last.length) / 4
            x, y = last.x + reach * math.cos(angle), last.y + reach * math.sin(angle)
        t = Table(_r(x), _r(y), yaw, length, side)
        if stratum == "walls" and not tables:
            t = _to_wall(t, rng, width, depth)
        if _fits(t, tables, width, depth):
            if stratum == "close" and tables and polygon_gap(t.corners(), tables[-1].corners()) > 1.0:
                continue
            return t
    return None


def _to_wall(t: Table, rng: random.Random, width: float, depth: float) -> Table:
    """The table moved 0.3-0.6 m from one wall (or two, a corner)."""
    gaps = t.wall_gaps(width, depth)
    walls = rng.sample(((0, 1), (2, 3)), 2 if rng.random() < 0.4 else 1)
    x, y = t.x, t.y
    for axis in walls:
        side = rng.choice(axis)
        shift = gaps[side] - rng.uniform(WALL_GAP + 0.01, 0.6)
        sign = 1 if side % 2 == 0 else -1
        if side < 2:
            x += sign * shift
        else:
            y += sign * shift
    return Table(_r(x), _r(y), t.yaw, t.length, t.width)


def _robot_free(p: Point, tables: list[Table], robots: list[Point], width: float, depth: float) -> bool:
    if abs(p[0]) > width / 2 - ROBOT_WALL or abs(p[1]) > depth / 2 - ROBOT_WALL:
        return False
    if any(point_gap(p, t.corners()) < ROBOT_TABLE for t in tables):
        return False
    return all(math.hypot(p[0] - q[0], p[1] - q[1]) >= ROBOT_GAP - 1e-9 for q in robots)


def _robots(rng: random.Random, n: int, tables: list[Table], width: float, depth: float, packed: bool
            ) -> list[Point] | None:
    robots: list[Point] = []
    if packed:  # a grid round one spot (a corner half the time), its nearest free points first
        step = rng.uniform(ROBOT_GAP, 1.0)
        if rng.random() < 0.5:
            cx, cy = rng.choice((-1, 1)) * (width / 2 - 0.6), rng.choice((-1, 1)) * (depth / 2 - 0.6)
        else:
            cx, cy = rng.uniform(-width / 2, width / 2), rng.uniform(-depth / 2, depth / 2)
        grid = [(cx + i * step, cy + j * step) for i in range(-8, 9) for j in range(-8, 9)]
        grid.sort(key=lambda p: (math.hypot(p[0] - cx, p[1] - cy), p))
        for p in grid:
            q = (_r(p[0]), _r(p[1]))
            if len(robots) < n and _robot_free(q, tables, robots, width, depth):
                robots.append(q)
    else:
        for _ in range(n):
            for _ in range(300):
                q = (_r(rng.uniform(-width / 2, width / 2)), _r(rng.uniform(-depth / 2, depth / 2)))
                if _robot_free(q, tables, robots, width, depth):
                    robots.append(q)
                    break
    return robots if len(robots) == n else None


def _failures(rng: random.Random, names: list[str]) -> list[dict[str, Any]]:
    kind = rng.choice(("one", "two", "rate"))
    if kind == "rate":
        return [{"rate": _r(rng.uniform(0.005, 0.05), 3), "reason": "roomgen: failure rate"}]
    chosen = rng.sample(names, 1 if kind == "one" else 2)
    return [{"robot": name, "at": _r(rng.uniform(2.0, 400.0)), "reason": "roomgen: failure"}
            for name in chosen]


def _features(rng: random.Random, stratum: str) -> set[str]:
    if stratum != "mixed":
        return {stratum}
    return {s for s in ("close", "walls", "narrow", "crowded", "failures", "loss") if rng.random() < 0.4}


def _layout(rng: random.Random, features: set[str]
            ) -> tuple[float, float, list[Table], list[Point]] | None:
    width, depth = _size(rng, "narrow" in features)
    k = rng.randint(2 if "close" in features else 1, 6)
    placing = "close" if "close" in features else ("walls" if "walls" in features else "open")
    tables: list[Table] = []
    for _ in range(k):
        t = _table(rng, width, depth, tables, placing if len(tables) < 2 or placing != "close" else "open")
        if t is None:
            return None
        tables.append(t)
    n = min(MAX_ROBOTS, 2 * k + rng.randint(0, 4))
    packed = "crowded" in features or ("crowded" not in features and rng.random() < 0.25)
    robots = _robots(rng, n, tables, width, depth, packed)
    return None if robots is None else (width, depth, tables, robots)


def draw(seed: int, stratum: str = "mixed") -> dict[str, Any]:
    """The scenario mapping (hfsm_sim.scenario) this seed draws for `stratum` (a key of STRATA)."""
    if stratum not in STRATA:
        raise ValueError(f"unknown stratum {stratum!r}; strata: {', '.join(STRATA)}")
    rng = random.Random(f"roomgen-{stratum}-{seed}")
    features = _features(rng, stratum)
    for _ in range(TRIES):
        layout = _layout(rng, features)
        if layout:
            break
    else:
        raise NoRoom(f"no room drawn for stratum {stratum!r}, seed {seed}")
    width, depth, tables, robots = layout
    names = [f"r{i + 1}" for i in range(len(robots))]
    scenario: dict[str, Any] = {
        "description": f"roomgen: stratum {stratum}, seed {seed}",
        "task": "table_to_wall",
        "room": {"width": _r(width), "depth": _r(depth)},
        "tables": [{"id": f"table{i + 1}", "x": t.x, "y": t.y, "yaw": t.yaw, "length": t.length,
                    "width": t.width, "priority": i + 1} for i, t in enumerate(tables)],
        "robots": {name: {"x": x, "y": y, "yaw": float(rng.randrange(-180, 180)), "body": "full"}
                   for name, (x, y) in zip(names, robots, strict=True)},
        "jitter": {"position": 0.1, "yaw": 10},
        "failures": _failures(rng, names) if "failures" in features else [],
    }
    if "loss" in features:
        scenario["radio"] = {"loss": _r(rng.uniform(0.05, 0.30))}
    return scenario


def write(path: Path, scenario: dict[str, Any]) -> None:
    """The scenario as an ordinary scenario file (`hfsm-run ... --scenario FILE`)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(yaml.safe_dump(scenario, sort_keys=False, default_flow_style=None), encoding="utf-8")
