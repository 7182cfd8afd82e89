"""Go to opposite side of table (Figure 7): walk around the table to the long side across
from the leader, and line up at its middle."""

from __future__ import annotations

import math
from collections.abc import Callable

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import (
    Point,
    Side,
    body_to_odom,
    distance,
    nearest_side,
    sides,
    table_frame,
)
from hfsm_behaviours.approach.navigate import (
    Guard,
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
from hfsm_behaviours.approach.way import CLEAR, choose, in_way, short_of
from hfsm_behaviours.body import Body
from hfsm_behaviours.drive.things import BEAMS, things
from hfsm_sim.perception.table_rect import TableRect

TABLE_YAWS = (0.0, 0.9, -0.9, 1.8, -1.8)
REACH = 2.0  # metres the range finder is read to, for the walk round
STRIDE = 0.75  # metres walked between two looks of the walk round
PAUSE = 1.0  # seconds stood short of a thing in the way before looking again
PATIENCE = 20  # looks stood short in all before the walk round gives up and squares up where it is
MOVES = 120  # strides, stops and legs of one walk round at most
CHANGES = 2  # changes of the end gone round after which the walk keeps the end it goes round

Sense = Callable[[], list[Point]]


def sensing(body: Body) -> Sense:
    """The things (robots; not walls, not a table on the floor) the range finder sees within REACH,
    each by its nearest point, in the odometry frame."""
    def sense() -> list[Point]:
        pose = body.odometry()
        return [body_to_odom(pose, p) for p in things(body.robot.scan(BEAMS, REACH + 0.5), REACH)]
    return sense


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


def opposite_side(rect: TableRect, leader: RobotSighting, robot: Point) -> Side:
    """The long side across from the leader (if the leader is not seen, the far one)."""
    near = leader.position if leader.found and math.isfinite(leader.position[0]) else robot
    across = nearest_side(rect, near)
    return next(s for s in sides(rect)[:2] if s != across)


def guarded(body: Body, sense: Sense | None) -> Guard | None:
    """For squaring up (navigate.square_up): the share of a move that stops CLEAR short of every
    thing sensed in its way."""
    if sense is None:
        return None

    def share(move: Point) -> float:
        pose = body.odometry()
        here, there = pose[:2], body_to_odom(pose, move)
        span = distance(here, there)
        return 1.0 if span < 1e-9 else distance(here, short_of(here, [there], sense(), CLEAR)) / span
    return share


def free_move(body: Body, moves: list[Point], sense: Sense | None) -> Point | None:
    """The first of `moves` ((forward, left) m, body frame) with no thing sensed in its way."""
    if sense is None:
        return moves[0]
    pose = body.odometry()
    seen = sense()
    free = (m for m in moves if not any(in_way(p, pose[:2], body_to_odom(pose, m), CLEAR) for p in seen))
    return next(free, None)


def end_of(rect: TableRect, points: list[Point]) -> float:
    """The end of the table (+1 or -1 along its axis) a way round goes by: that of its first point
    beyond an end; 0 when it goes straight to the side."""
    ends = [x for x, _ in (table_frame(rect, p) for p in points[:-1]) if abs(x) > rect.length / 2]
    return math.copysign(1.0, ends[0]) if ends else 0.0


def walk_round(body: Body, rect: TableRect, target: Side, margin: float, gap: float, legs: int,
               refreshed: Callable[[TableRect], TableRect], sense: Sense | None) -> tuple[TableRect, Side]:
    """Walk round the table to `gap` out from the target side's middle, looking again at each
    corner. With `sense` (in a room): the way round whose legs the range finder sees free, in
    strides of STRIDE m, stopping short of a thing in the way of both (approach.way)."""
    corners = stops = changes = 0
    went = keep = 0.0
    for _ in range(MOVES):
        if corners >= legs or stops >= PATIENCE:
            break
        here = body.odometry()[:2]
        way = choose(rect, here, target, margin, gap, sense() if sense else [],
                     keep=keep if changes >= CHANGES else 0.0)
        point = way.points[0]
        end = end_of(rect, way.points)
        if end != 0.0:
            changes += went != 0.0 and end != went
            went = keep = end
        if way.stop:
            walk_to(body, point)
            body.ctx.wait(PAUSE)
            stops += 1
            continue
        if sense is not None and distance(here, point) > STRIDE:
            ux, uy = point[0] - here[0], point[1] - here[1]
            k = STRIDE / math.hypot(ux, uy)
            walk_to(body, (here[0] + k * ux, here[1] + k * uy))
            continue
        walk_to(body, point)
        if len(way.points) == 1:
            break
        rect = refreshed(rect)
        target = nearest_side(rect, target.middle)
        corners += 1
    return rect, target


def good_view(rect: TableRect, known: TableRect, look: Look, min_points: int) -> bool:
    """Whole enough to plan on: the leader's measure of the table, or enough outline."""
    if known.length > 0:
        return agrees(rect, known, look.size_tolerance)
    return rect.found and rect.points >= min_points


def clear_view(body: Body, look: Look, known: TableRect, own: int, step: float,
               views: int, min_points: int, in_line: float, sense: Sense | None = None) -> TableRect:
    """The table top, moving for a better view while too little of it shows (far away, or
    hidden behind the leader): closer if the leader is not in the line of sight, else
    sideways away from it. With `sense` (in a room), a move with a thing in its way is made the
    other way sideways, or not at all."""
    rect = look_at_table(body, None, look)
    for _ in range(views):
        if good_view(rect, known, look, min_points):
            break
        table = see_table(body, 0.0, look.pitch)
        leader = see_robot(body, 0.0, look.pitch, own)
        blocked = leader.found and abs(leader.bearing) < in_line
        if table is not None and not blocked and table.distance > 2 * step:
            moves = [(step, 0.0)]
        else:
            side = -math.copysign(step, leader.bearing if leader.found else -1.0)
            moves = [(0.0, side), (0.0, -side)]
        move = free_move(body, moves, sense)
        if move is None:
            break
        if move[0]:
            body.walk(move[0])
        else:
            body.crab(move[1])
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
    sense = sensing(body) if named_at is not None else None
    rect = clear_view(body, look, known, own, step, views, min_points, in_line, sense)
    if not rect.found:
        return Outcome("lost")
    leader = scan_for_robot(body, [0.0, 0.6, -0.6, 1.2, -1.2], pitch, own, leader_colour, named_at)
    target = opposite_side(rect, leader, body.odometry()[:2])
    rect, target = walk_round(body, rect, target, margin, gap, legs,
                              lambda r: refresh(body, r, look, known if known.length > 0 else None), sense)
    tol = Tolerance(along_tolerance, out_tolerance, yaw_tolerance)
    rect, _, ok = align_to_side(body, rect, target.middle, gap, look, tol, tries,
                                known if known.length > 0 else None, guarded(body, sense))
    if not leader_behind_table(body, pitch, own, leader_colour, named_at):
        return Outcome("leader_not_across", leader_seen=leader.found)
    return Outcome("at_opposite_side" if ok else "not_aligned", leader_seen=leader.found)
