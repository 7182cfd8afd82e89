"""Go to opposite side of table (Figure 7): walk around the table to the long side across
from the leader, and line up at its middle."""

from __future__ import annotations

import math

from behaviours.approach.frames import Point, Side, from_table_frame, nearest_side, sides, table_frame
from behaviours.approach.navigate import Look, Tolerance, align_to_side, look_at_table, walk_to
from behaviours.approach.sight import RobotSighting, own_colour, scan_for_robot, see_table
from behaviours.body import Body
from hfsm.primitive import Context, Outcome, primitive
from sim.perception.table_rect import TableRect

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


@primitive(outcomes=["at_opposite_side", "not_aligned", "lost"], failures=["not_aligned", "lost"],
           outputs=["leader_seen"], world="sim")
def go_to_opposite_side_of_table(
        ctx: Context, *, gap: float = 0.35, margin: float = 0.5, pitch: float = 0.3,
        spread: float = 0.7, along_tolerance: float = 0.03, out_tolerance: float = 0.03,
        yaw_tolerance: float = 0.05, tries: int = 4, legs: int = 4) -> Outcome:
    """Face the table, see where the leader stands, walk round the table (`margin` m clear
    of its corners) to the other long side and square up `gap` m out from its middle."""
    body = Body(ctx)
    look = Look(pitch=pitch, spread=spread)
    if not face_table(body, pitch):
        return Outcome("lost")
    rect = look_at_table(body, None, look)
    if not rect.found:
        return Outcome("lost")
    leader = scan_for_robot(body, [0.0, 0.6, -0.6, 1.2, -1.2], pitch, own_colour(body))
    target = opposite_side(rect, leader, body.odometry()[:2])
    for _ in range(legs):
        points = route(rect, body.odometry()[:2], target, margin, gap)
        walk_to(body, points[0])
        if len(points) == 1:
            break
        fresh = look_at_table(body, rect, look)
        if fresh.found:
            rect, target = fresh, nearest_side(fresh, target.middle)
    tol = Tolerance(along_tolerance, out_tolerance, yaw_tolerance)
    rect, _, ok = align_to_side(body, rect, target.middle, gap, look, tol, tries)
    return Outcome("at_opposite_side" if ok else "not_aligned", leader_seen=leader.found)
