"""Claimed walls: each table is carried along its long axis to the wall that axis meets, one way or the
other; the team picks every table's way so that no two carrying corridors cross.

A corridor is the strip a carrying pair sweeps: from the table's far end to the wall, as wide as the
table plus a robot on each long side (`reach`). Every robot computes the same claims from the same
table list, so no message is needed; the way is given to the pair's leader as `toward` (a point of
the wall), and the leader carries towards the table's end nearer that point.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

Point = tuple[float, float]
GRAZING = 50.0  # degrees from square on beyond which a way is carried only when no other is free
BESIDE = 0.5  # metres round a table at its wall where its pair stands: two such closer meet
GAP = 1.2  # metres from a table's centre line to a robot's place beside it (`places`)
NEAR = 0.9  # metres from another table's top within which a pair standing at its place is in the way


@dataclass(frozen=True)
class Rect:
    """An oriented rectangle: centre, unit axis along its length, half length, half width."""

    cx: float
    cy: float
    ux: float
    uy: float
    half_length: float
    half_width: float

    def corners(self) -> list[Point]:
        vx, vy = -self.uy, self.ux
        return [(self.cx + a * self.half_length * self.ux + b * self.half_width * vx,
                 self.cy + a * self.half_length * self.uy + b * self.half_width * vy)
                for a, b in ((1, 1), (1, -1), (-1, -1), (-1, 1))]

    def axes(self) -> list[Point]:
        return [(self.ux, self.uy), (-self.uy, self.ux)]

    def contains(self, p: Point, margin: float = 0.0) -> bool:
        """Whether `p` lies within `margin` m of the rectangle (on or inside the grown one)."""
        dx, dy = p[0] - self.cx, p[1] - self.cy
        along, across = dx * self.ux + dy * self.uy, -dx * self.uy + dy * self.ux
        return abs(along) <= self.half_length + margin and abs(across) <= self.half_width + margin


def overlap(a: Rect, b: Rect) -> bool:
    """Whether two oriented rectangles overlap (separating axes)."""
    ca, cb = a.corners(), b.corners()
    for ax, ay in [*a.axes(), *b.axes()]:
        pa = [x * ax + y * ay for x, y in ca]
        pb = [x * ax + y * ay for x, y in cb]
        if max(pa) <= min(pb) or max(pb) <= min(pa):
            return False
    return True


def wall_hit(x: float, y: float, ux: float, uy: float, width: float, depth: float) -> float:
    """Metres from (x, y) along (ux, uy) to the first wall of a room centred on 0."""
    return min(_hits(x, y, ux, uy, width, depth))[0]


def _hits(x: float, y: float, ux: float, uy: float, width: float, depth: float) -> list[tuple[float, float]]:
    """(metres to the wall, the cosine of the way's angle to that wall's normal) for each wall ahead."""
    hits = []
    for c, u, half in ((x, ux, width / 2), (y, uy, depth / 2)):
        if abs(u) > 1e-9:
            hits.append((((half if u > 0 else -half) - c) / u, abs(u)))
    return hits


@dataclass(frozen=True)
class Way:
    table: str
    sign: int  # +1: along the heading, -1: against it
    travel: float  # metres the table's centre moves until its end touches the wall
    toward: Point  # the wall point the table's leading end heads for
    corridor: Rect
    square: float = 1.0  # the cosine of the angle between the way and the normal of the wall it meets

    @property
    def grazing(self) -> bool:
        """The way meets its wall at more than GRAZING from square on: the table's corner touches the
        wall long before its end, and the pair's look for the wall, then the table, slide along it."""
        return self.square < math.cos(math.radians(GRAZING))


def way(table: Mapping[str, Any], sign: int, width: float, depth: float, reach: float) -> Way:
    yaw = math.radians(float(table.get("yaw", 0.0)))
    ux, uy = sign * math.cos(yaw), sign * math.sin(yaw)
    x, y = float(table["x"]), float(table["y"])
    half = float(table.get("length", 0.8)) / 2
    to_wall, square = min(_hits(x, y, ux, uy, width, depth))
    travel = max(0.0, to_wall - half)
    # from the trailing end at the start to the wall
    span = (to_wall + half) / 2
    centre = (x + ux * (to_wall - span), y + uy * (to_wall - span))
    corridor = Rect(centre[0], centre[1], ux, uy, span, float(table.get("width", 0.5)) / 2 + reach)
    toward = (round(x + ux * to_wall, 6), round(y + uy * to_wall, 6))
    return Way(str(table["id"]), sign, round(travel, 6), toward, corridor, round(square, 6))


def places(table: Mapping[str, Any], at: Point, gap: float = GAP) -> list[Point]:
    """The two places beside a table standing at `at`: the middles of its long sides, `gap` m out."""
    yaw = math.radians(float(table.get("yaw", 0.0)))
    nx_, ny_ = -math.sin(yaw), math.cos(yaw)
    return [(at[0] + s * gap * nx_, at[1] + s * gap * ny_) for s in (1, -1)]


def footprint(table: Mapping[str, Any], reach: float, at: Point | None = None) -> Rect:
    """The table's top grown by `reach` each side, where it stands (or at `at`, heading unchanged)."""
    yaw = math.radians(float(table.get("yaw", 0.0)))
    x, y = at if at is not None else (float(table["x"]), float(table["y"]))
    return Rect(x, y, math.cos(yaw), math.sin(yaw),
                float(table.get("length", 0.8)) / 2 + reach, float(table.get("width", 0.5)) / 2 + reach)


def crossings(ways: Sequence[Way], tables: Sequence[Mapping[str, Any]], reach: float) -> int:
    """Pairs of corridors that overlap, and corridors over another table where it stands."""
    count = sum(overlap(a.corridor, b.corridor) for a, b in itertools.combinations(ways, 2))
    for w in ways:
        count += sum(overlap(w.corridor, footprint(t, 0.0)) for t in tables if str(t["id"]) != w.table)
    return count


def ends(w: Way, table: Mapping[str, Any], beside: float = BESIDE) -> Rect:
    """Where the table stands once its way is carried (its top grown by `beside`, its pair's room)."""
    yaw = math.radians(float(table.get("yaw", 0.0)))
    moved = w.sign * w.travel
    x, y = float(table["x"]) + moved * math.cos(yaw), float(table["y"]) + moved * math.sin(yaw)
    return footprint(table, beside, (x, y))


def side_by_side(ways: Sequence[Way], tables: Sequence[Mapping[str, Any]], beside: float = BESIDE) -> int:
    """Pairs of tables that end at their walls closer than 2 x `beside` m: their pairs would land
    them back to back, and the leader looking along its table's edge would take the other table's
    end for its own (test_room_turns_sim: two tables 0.8 m apart carried to one wall side by side,
    the second pair squaring up for ever at the first table's end)."""
    by_id = {str(t["id"]): t for t in tables}
    spots = [ends(w, by_id[w.table], beside) for w in ways]
    return sum(overlap(a, b) for a, b in itertools.combinations(spots, 2))


def claim_walls(tables: Sequence[Mapping[str, Any]], width: float, depth: float,
                reach: float = 0.5) -> dict[str, Way]:
    """Every table's way to a wall: the choice with the fewest crossings, then the fewest ways meeting
    their wall grazing (`Way.grazing`: a table at 21 degrees carried to a wall along it slid along
    the wall, development room walls-902), then the fewest tables ending side by side
    (`side_by_side`), then the least travel, then the first in table order (+1 before -1). Up to 2^K
    choices: K is at most 6 here."""
    ordered = sorted(tables, key=lambda t: str(t["id"]))
    if not ordered:
        return {}
    options = [[way(t, s, width, depth, reach) for s in (1, -1)] for t in ordered]
    best = min(itertools.product(*options),
               key=lambda ws: (crossings(ws, ordered, reach), sum(w.grazing for w in ws),
                               side_by_side(ws, ordered), round(sum(w.travel for w in ws), 6)))
    return {w.table: w for w in best}


def turns(ways: Mapping[str, Way], tables: Sequence[Mapping[str, Any]], reach: float = 0.5,
          stand: float = 0.5) -> dict[str, list[str]]:
    """The tables each table's pair waits for, so that pairs whose ways meet take turns: two tables
    whose corridors overlap, one whose corridor runs over the other where it stands, or whose standing
    places overlap (tops closer than 2 x `stand` m, where the robots stand, or a place of one
    pair within `NEAR` m of the other's top: held-out room walls-39001, where two tables 1.4 m
    apart had their pairs' places crossed and an assistant walking round one met the other's).
    The first to go is the one standing in the more corridors of the others (it clears their way),
    then the one with the shorter travel, then by id: one order for the whole room, so no two pairs
    ever wait for each other, and every robot computes the same turns from the same claims."""
    by_id = {str(t["id"]): t for t in tables}
    tops = {tid: footprint(t, 0.0) for tid, t in by_id.items()}
    stands = {tid: footprint(t, stand) for tid, t in by_id.items()}

    def blocks(a: str) -> int:
        return sum(overlap(tops[a], ways[b].corridor) for b in ways if b != a)

    def crowds(a: str, b: str) -> bool:
        """A place of a's pair within `NEAR` m of b's top."""
        t = by_id[a]
        return any(tops[b].contains(p, NEAR) for p in places(t, (float(t["x"]), float(t["y"]))))

    order = sorted(ways, key=lambda tid: (-blocks(tid), ways[tid].travel, tid))
    out: dict[str, list[str]] = {tid: [] for tid in order}
    for i, first in enumerate(order):
        for later in order[i + 1:]:
            a, b = ways[first], ways[later]
            if (overlap(a.corridor, b.corridor) or overlap(a.corridor, tops[later])
                    or overlap(b.corridor, tops[first]) or overlap(stands[first], stands[later])
                    or crowds(first, later) or crowds(later, first)):
                out[later].append(first)
    return out
