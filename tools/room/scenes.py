"""Issue 10's rooms (the long run's, tools/longrun.py; the campaign now draws from hfsm_sim/roomgen.py),
as data for hfsm_sim/scenario.py: K tables of different sizes, positions and
headings, one pair of humanoids beside each table (on either long side, facing it, as the shipped
`room_*` scenarios start them), the N - 2K others standing free, all drawn from the seed.

A room is kept only when it can be cleared as machines/clear_room.yaml clears rooms: every table's
zone (the table and its pair) apart from every other, every table with room to move along its long
axis, and claimed walls (hfsm_behaviours.room.claims) whose corridors cross nothing (no other corridor, no
other table, no robot standing where it starts). Otherwise another room is drawn, from the same
seeded generator, so a seed always gives the same room.
"""

from __future__ import annotations

import math
import random
from typing import Any

from hfsm_behaviours.room.claims import Rect, claim_walls, crossings, overlap

PAIR_GAP = 1.2  # metres from the table's centre line to each robot of its pair (room_3_tables)
ROBOT = 0.35  # half the side of the square a standing robot is checked as
WALL_MARGIN = 0.5  # metres from a robot's centre to the nearest wall, at least
REACH = 0.5  # clear_room's default `reach`
LENGTHS = (0.7, 0.8, 0.9, 1.0)
WIDTHS = (0.45, 0.5, 0.55)
HEADINGS = (0, 90, 180, 270)
TRIES = 2000


class NoRoom(Exception):
    """No solvable room was drawn for these numbers (too many tables for the room's size)."""


def room_size(k: int, rng: random.Random) -> tuple[float, float]:
    """Width and depth in metres: 7-8 x 5-6 for two tables, one metre more each way a table more."""
    width = 7.0 + (k - 2) + rng.choice((0.0, 0.5, 1.0))
    depth = 5.0 + 0.75 * (k - 2) + rng.choice((0.0, 0.5, 1.0))
    return width, depth


def _square(x: float, y: float) -> Rect:
    return Rect(x, y, 1.0, 0.0, ROBOT, ROBOT)


def _zone(t: dict[str, Any]) -> Rect:
    yaw = math.radians(t["yaw"])
    return Rect(t["x"], t["y"], math.cos(yaw), math.sin(yaw), t["length"] / 2 + 0.3, PAIR_GAP + ROBOT + 0.1)


def _inside(x: float, y: float, width: float, depth: float) -> bool:
    return abs(x) <= width / 2 - WALL_MARGIN and abs(y) <= depth / 2 - WALL_MARGIN


def _table(i: int, width: float, depth: float, rng: random.Random) -> dict[str, Any] | None:
    """Table i with its pair, or None when it does not fit where it was drawn."""
    length, side = rng.choice(LENGTHS), rng.choice(WIDTHS)
    yaw = rng.choice(HEADINGS)
    x = round(rng.uniform(-width / 2 + 0.5, width / 2 - 0.5), 2)
    y = round(rng.uniform(-depth / 2 + 0.5, depth / 2 - 0.5), 2)
    ux, uy = round(math.cos(math.radians(yaw))), round(math.sin(math.radians(yaw)))
    ends = [(x + s * ux * (length / 2 + 0.6), y + s * uy * (length / 2 + 0.6)) for s in (1, -1)]
    if not all(abs(ex) < width / 2 and abs(ey) < depth / 2 for ex, ey in ends):
        return None  # less than 0.6 m to move one way or the other: hardly a carry
    shift = round(rng.uniform(-0.2, 0.2), 2)
    robots = []
    for s in (1, -1):  # s = 1: on the left of the heading, facing right
        rx = round(x - s * uy * PAIR_GAP + ux * shift, 2)
        ry = round(y + s * ux * PAIR_GAP + uy * shift, 2)
        if not _inside(rx, ry, width, depth):
            return None
        robots.append({"x": rx, "y": ry, "yaw": (yaw - 90 * s + 180) % 360 - 180})
    return {"id": f"table{i + 1}", "x": x, "y": y, "yaw": yaw, "length": length, "width": side,
            "priority": i + 1, "pair": robots}


def _free(x: float, y: float, rects: list[Rect], robots: list[dict[str, Any]]) -> bool:
    me = _square(x, y)
    return not any(overlap(me, r) for r in rects) and all(
        math.hypot(x - r["x"], y - r["y"]) >= 0.9 for r in robots)


def _draw(k: int, n: int, rng: random.Random) -> dict[str, Any] | None:
    width, depth = room_size(k, rng)
    tables: list[dict[str, Any]] = []
    for i in range(k):
        for _ in range(50):
            t = _table(i, width, depth, rng)
            if t and not any(overlap(_zone(t), _zone(o)) for o in tables):
                tables.append(t)
                break
        else:
            return None
    plain = [{key: v for key, v in t.items() if key != "pair"} for t in tables]
    ways = claim_walls(plain, width, depth, REACH)
    if crossings(list(ways.values()), plain, REACH):
        return None
    pairs = [r for t in tables for r in t["pair"]]
    for t in tables:
        others = [r for o in tables if o is not t for r in o["pair"]]
        if any(overlap(ways[t["id"]].corridor, _square(r["x"], r["y"])) for r in others):
            return None
    keep_out = [w.corridor for w in ways.values()] + [_zone(t) for t in tables]
    free: list[dict[str, Any]] = []
    for _ in range(n - 2 * k):
        for _ in range(200):
            x = round(rng.uniform(-width / 2 + WALL_MARGIN, width / 2 - WALL_MARGIN), 2)
            y = round(rng.uniform(-depth / 2 + WALL_MARGIN, depth / 2 - WALL_MARGIN), 2)
            if _free(x, y, keep_out, pairs + free):
                free.append({"x": x, "y": y, "yaw": rng.choice((0, 90, 180, -90))})
                break
        else:
            return None
    robots = {f"r{i + 1}": {**r, "body": "full"} for i, r in enumerate(pairs + free)}
    return {"room": {"width": width, "depth": depth}, "tables": plain, "robots": robots}


def room(seed: int, k: int, n: int, *, failure: bool = False, fail_window: tuple[float, float] = (5.0, 150.0)
         ) -> dict[str, Any]:
    """A scenario mapping: the room of `k` tables and `n` robots this seed draws; with `failure`, one
    robot (drawn from the seed) fails at a time drawn uniformly in `fail_window` simulated seconds."""
    if not 2 * k <= n:
        raise ValueError(f"{n} robots cannot make {k} pairs")
    rng = random.Random(f"room-{seed}-{k}-{n}")
    for _ in range(TRIES):
        drawn = _draw(k, n, rng)
        if drawn:
            break
    else:
        raise NoRoom(f"no solvable room of {k} tables and {n} robots in {TRIES} draws (seed {seed})")
    failures = []
    if failure:
        robot = rng.choice(sorted(drawn["robots"], key=lambda r: int(r[1:])))
        at = round(rng.uniform(*fail_window), 1)
        failures.append({"robot": robot, "at": at, "reason": "bench: random failure"})
    return {
        "description": f"room bench: {k} tables, {n} humanoids, seed {seed}",
        "task": "table_to_wall",
        **drawn,
        "jitter": {"position": 0.1, "yaw": 10},
        "failures": failures,
    }
