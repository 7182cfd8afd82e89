"""Go to opposite side of table (Figure 7): walk around the table to the long side across
from the leader, and line up at its middle."""

from __future__ import annotations

import math

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import Point, Side, from_table_frame, nearest_side, sides, table_frame
from hfsm_behaviours.approach.navigate import (
    Look,
    Tolerance,
    agrees,
    align_to_side,
    look_at_table,
    refresh,
    turn_to,
    walk_to,
)
from hfsm_behaviours.approach.sight import (
    RobotSighting,
    leader_behind_table,
    named,
    own_colour,
    scan_for_robot,
    see_robot,
    see_table,
)
from hfsm_behaviours.body import Body
from hfsm_sim.perception.table_rect import TableRect

TABLE_YAWS = (0.0, 0.9, -0.9, 1.8, -1.8)


def face_table(body: Body, pitch: float) -> bool:
    """Find the table with the head (turning round once if need be) and face it."""
    for _ in range(2):
        for yaw in TABLE_YAWS:
            seen = see_table(body, yaw, pitch)
            if seen is not None:
                body.turn(seen.bearing)
                return True
        body.turn(math.pi)
    return False


def route(rect: TableRect, robot: Point, target: Side, margin: float, gap: float) -> list[Point]:
    """Waypoints to `gap` out from the target side's middle, round the corners `margin` out,
    never along the other long side's middle."""
    x, y = table_frame(rect, robot)
    t = 1.0 if table_frame(rect, target.middle)[1] >= 0 else -1.0
    half_l, half_w = rect.length / 2, rect.width / 2
    sx = 1.0 if x >= 0 else -1.0
    points: list[Point] = []
    if y * t < half_w + gap / 2:
        if y * t < -half_w:
            points.append((sx * (half_l + margin), -t * (half_w + margin)))
        points.append((sx * (half_l + margin), t * (half_w + margin)))
    points.append((0.0, t * (half_w + gap)))
    return [from_table_frame(rect, p) for p in points]


def opposite_side(rect: TableRect, leader: RobotSighting, robot: Point) -> Side:
    """The long side across from the leader (if the leader is not seen, the far one)."""
    near = leader.position if leader.found and math.isfinite(leader.position[0]) else robot
    across = nearest_side(rect, near)
    return next(s for s in sides(rect)[:2] if s != across)


def good_view(rect: TableRect, known: TableRect, look: Look, min_points: int) -> bool:
    """Whole enough to plan on: the leader's measure of the table, or enough outline."""
    if known.length > 0:
        return agrees(rect, known, look.size_tolerance)
    return rect.found and rect.points >= min_points


def clear_view(body: Body, look: Look, known: TableRect, own: int, step: float,
               views: int, min_points: int, in_line: float) -> TableRect:
    """The table top, moving for a better view while too little of it shows (far away, or
    hidden behind the leader): closer if the leader is not in the line of sight, else
    sideways away from it."""
    rect = look_at_table(body, None, look)
    for _ in range(views):
        if good_view(rect, known, look, min_points):
            break
        table = see_table(body, 0.0, look.pitch)
        leader = see_robot(body, 0.0, look.pitch, own)
        blocked = leader.found and abs(leader.bearing) < in_line
        if table is not None and not blocked and table.distance > 2 * step:
            body.walk(step)
        else:
            body.crab(-math.copysign(step, leader.bearing if leader.found else -1.0))
        face_table(body, look.pitch)
        rect = look_at_table(body, None, look)
    return rect


@primitive(outcomes=["at_opposite_side", "not_aligned", "leader_not_across", "lost"],
           failures=["not_aligned", "leader_not_across", "lost"],
           outputs=["leader_seen"], world="sim")
def go_to_opposite_side_of_table(
        ctx: Context, *, gap: float = 0.35, margin: float = 0.5, pitch: float = 0.3,
        spread: float = 0.7, along_tolerance: float = 0.03, out_tolerance: float = 0.03,
        yaw_tolerance: float = 0.05, tries: int = 4, legs: int = 4, length: float = 0.0,
        width: float = 0.0, step: float = 0.5, views: int = 6, min_points: int = 60,
        in_line: float = 0.35, table: list[float] | None = None, gate: float = 0.6,
        leader_colour: int = -1) -> Outcome:
    """Face the table, see where the leader stands, walk round the table (`margin` m clear
    of its corners) to the other long side and square up `gap` m out from its middle; check
    that the leader now stands behind the table (its blob above the table's). `length` and
    `width`: the table as the leader measured it (0: unknown), to tell a whole view. With a
    `table` ([x, y], own start frame): the table seen nearest it, within `gate` m. With a
    `leader_colour` (>= 0, as the leader said it): only a robot of that colour is the leader, and
    with a `table` too, the one of that colour nearest the table (colours repeat beyond ten)."""
    body = Body(ctx)
    named_at = named(table)
    look = Look(pitch=pitch, spread=spread, target=named_at, gate=gate)
    if named_at is not None:
        x, y, _ = body.odometry()
        turn_to(body, math.atan2(named_at[1] - y, named_at[0] - x))
    elif not face_table(body, pitch):
        return Outcome("lost")
    own = own_colour(body)
    known = TableRect(True, length=length, width=width)
    rect = clear_view(body, look, known, own, step, views, min_points, in_line)
    if not rect.found:
        return Outcome("lost")
    leader = scan_for_robot(body, [0.0, 0.6, -0.6, 1.2, -1.2], pitch, own, leader_colour, named_at)
    target = opposite_side(rect, leader, body.odometry()[:2])
    for _ in range(legs):
        points = route(rect, body.odometry()[:2], target, margin, gap)
        walk_to(body, points[0])
        if len(points) == 1:
            break
        rect = refresh(body, rect, look, known if known.length > 0 else None)
        target = nearest_side(rect, target.middle)
    tol = Tolerance(along_tolerance, out_tolerance, yaw_tolerance)
    rect, _, ok = align_to_side(body, rect, target.middle, gap, look, tol, tries,
                                known if known.length > 0 else None)
    if not leader_behind_table(body, pitch, own, leader_colour, named_at):
        return Outcome("leader_not_across", leader_seen=leader.found)
    return Outcome("at_opposite_side" if ok else "not_aligned", leader_seen=leader.found)
