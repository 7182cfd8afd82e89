"""Moves by dead reckoning in the odometry frame, and lining up square on a table's side."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from hfsm_behaviours.approach.frames import Point, Side, bearing_to, distance, nearest_side, wrap
from hfsm_behaviours.approach.sight import observe_table, observe_tables
from hfsm_behaviours.body import Body
from hfsm_sim.perception import NO_RECT, TableRect, pick_table


@dataclass(frozen=True)
class Look:
    """How to look at the table top: head pitch, yaw spread between views, views, and the
    brightness share that marks the top face. With a `target` (odometry frame: where a task
    says its table is), only the table seen nearest it, within `gate` metres, is the table."""

    pitch: float = 0.3
    spread: float = 0.7
    views: int = 3
    value_ratio: float = 0.9
    size_tolerance: float = 0.1
    target: Point | None = None
    gate: float = 0.6


@dataclass(frozen=True)
class Tolerance:
    along: float = 0.03
    out: float = 0.03
    yaw: float = 0.05


def turn_to(body: Body, heading: float) -> None:
    body.turn(wrap(heading - body.odometry()[2]))


def walk_to(body: Body, point: Point) -> None:
    """Turn towards a point and walk straight to it."""
    body.turn(bearing_to(body.odometry(), point))
    body.walk(distance(body.odometry()[:2], point))


def look_at_table(body: Body, rect: TableRect | None, look: Look) -> TableRect:
    """A fresh rectangle, looking towards where the table was last seen (else towards the
    target, else ahead). With a target, the table seen nearest to where it was last seen (else
    to the target) is the one."""
    last = (rect.x, rect.y) if rect and rect.found else look.target
    centre = bearing_to(body.odometry(), last) if last else 0.0
    if look.target is None or last is None:
        return observe_table(body, centre, look.spread, look.pitch, look.value_ratio, look.views)
    seen = observe_tables(body, centre, look.spread, look.pitch, look.value_ratio, look.views)
    picked = pick_table(seen, last, look.gate)
    return picked.rect if picked else NO_RECT


def agrees(fresh: TableRect, ref: TableRect, size_tolerance: float) -> bool:
    """A fresh sighting is trusted when its sides measure as the reference's did: a partial
    or occluded view gives a smaller or turned rectangle."""
    return (fresh.found and abs(fresh.length - ref.length) <= size_tolerance
            and abs(fresh.width - ref.width) <= size_tolerance)


def refresh(body: Body, rect: TableRect, look: Look, known: TableRect | None = None) -> TableRect:
    """Look again; keep the old rectangle if the new one does not measure as the `known`
    table (default: the old rectangle)."""
    fresh = look_at_table(body, rect, look)
    return fresh if agrees(fresh, known or rect, look.size_tolerance) else rect


Guard = Callable[[Point], float]  # a move (forward, left m, body frame) -> the share of it that is free


def square_up(body: Body, side: Side, gap: float, guard: Guard | None = None) -> None:
    """Face the table across `side`, then walk and crab to `gap` out from its middle (with a
    `guard`, each move only as far as it lets)."""
    turn_to(body, side.facing())
    along, out = side.offset(body.odometry()[:2])
    walk = out - gap
    body.walk(walk * (guard((walk, 0.0)) if guard else 1.0))
    body.crab(along * (guard((0.0, along)) if guard else 1.0))


def errors(body: Body, side: Side, gap: float) -> tuple[float, float, float]:
    """(along, out, yaw) errors of the robot from its place `gap` out from the side's middle."""
    x, y, yaw = body.odometry()
    along, out = side.offset((x, y))
    return along, out - gap, wrap(side.facing() - yaw)


def within(errs: tuple[float, float, float], tol: Tolerance) -> bool:
    along, out, yaw = errs
    return abs(along) <= tol.along and abs(out) <= tol.out and abs(yaw) <= tol.yaw


def align_to_side(body: Body, rect: TableRect, near: Point, gap: float, look: Look,
                  tol: Tolerance, tries: int, known: TableRect | None = None, guard: Guard | None = None
                  ) -> tuple[TableRect, Side, bool]:
    """Look, then square up on the long side nearest to `near`, until within tolerance.
    Returns the last rectangle, the side and whether the tolerance was met."""
    side = nearest_side(rect, near)
    for _ in range(tries):
        rect = refresh(body, rect, look, known)
        side = nearest_side(rect, side.middle)
        if within(errors(body, side, gap), tol):
            return rect, side, True
        square_up(body, side, gap, guard)
    return rect, side, within(errors(body, side, gap), tol)


def unit(x: float, y: float) -> Point:
    norm = math.hypot(x, y)
    return (x / norm, y / norm) if norm > 1e-9 else (0.0, 0.0)
