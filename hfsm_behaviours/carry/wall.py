"""Which way to carry, and whether the table is at the wall (the leader's looks; Figure 6)."""

from __future__ import annotations

import math

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.body import Body
from hfsm_behaviours.carry.sensing import edge, extent, side_sign, wall
from hfsm_sim.perception import WallSeen

MIN_CLOSING = 0.3  # a wall more than ~72 degrees off square to the carry cannot be judged by eye


@primitive(outcomes=["chosen", "failure"], outputs=["direction", "distance"], world="sim")
def choose_carry_direction(
    ctx: Context, *, look_yaw: float = 2.0, look_pitch: float = 0.5, toward: list[float] | None = None
) -> str | Outcome:
    """Look left and right along the table's long axis and choose the side whose wall is
    nearer (a tie goes left), among the walls the table's end can meet: a wall seen that runs
    along the carry (one close behind the robot, in a room of many tables) counts only when no
    other is seen. With `toward` ([x, y] m in the own start frame, e.g. a wall segment the team
    claimed), the side that point lies on. Outputs `direction`
    ('left'/'right', in this robot's frame) and `distance` (m) to that side's wall (-1: not
    seen). `failure` when no wall is seen on either side and no point is given."""
    body = Body(ctx)
    seen = {side: wall(body, side, look_yaw, look_pitch) for side in ("left", "right")}
    body.look(0.0, 0.0)
    found = {side: w.distance for side, w in seen.items() if w.found}
    meets = {side: d for side, d in found.items()
             if side_sign(side) * math.sin(seen[side].normal) >= MIN_CLOSING}
    found = meets or found
    if toward:
        x, y, yaw = body.odometry()
        across = -math.sin(yaw) * (toward[0] - x) + math.cos(yaw) * (toward[1] - y)
        side = "left" if across >= 0 else "right"
        return Outcome("chosen", direction=side, distance=round(found.get(side, -1.0), 3))
    if not found:
        return "failure"
    side = min(found, key=lambda s: (found[s], s != "left"))
    return Outcome("chosen", direction=side, distance=round(found[side], 3))


def room_to_wall(seen: WallSeen, corners: list[tuple[float, float]], sign: float) -> float:
    """How far (m) the table can move along the body's side axis (`sign`: +1 left, -1 right)
    before its first corner (body frame) meets the wall line: square or oblique, the line as
    seen, not only its distance. Infinite when the wall runs nearly along that axis."""
    nx, ny = math.cos(seen.normal), math.sin(seen.normal)
    closing = sign * ny  # how fast a move along the axis nears the wall
    if closing < MIN_CLOSING:
        return math.inf
    return min((seen.distance - nx * x - ny * y) / closing for x, y in corners)


@primitive(outcomes=["reached", "not_reached", "failure"], outputs=["steps", "gap"],
           world="sim")
def table_at_wall(
    ctx: Context,
    *,
    direction: str,
    wall_gap: float = 0.05,
    steps: int = 10,
    step: float = 0.05,
    width: float = 0.0,
    wall_yaw: float = 2.0,
    wall_pitch: float = 0.5,
    table_yaw: float = 1.3,
    table_pitch: float = 0.45,
    edge_pitch: float = 0.5,
) -> str | Outcome:
    """Figure 6, on the floor: look down at the near edge (its angle and distance), toward
    `direction` for the wall's foot (a line, fitted) and along the table for its far end; the
    gap is how far the table's end can move that way before one of its corners meets the wall
    line - the near edge's corner, and the far edge's `width` m beyond it (0: unknown), so that
    an oblique wall is met by the right corner.
    `reached` when the gap is at most `wall_gap` m; else `not_reached` with `steps`: how many
    steps of `step` m to take this cycle (at most `steps`, never more than the gap holds, at
    least 1). `failure` when the wall or the table is not seen, or the wall runs nearly along
    the carry."""
    body = Body(ctx)
    near = edge(body, edge_pitch)
    seen_wall = wall(body, direction, wall_yaw, wall_pitch)
    reach = extent(body, direction, table_yaw, table_pitch, near.turn if near.found else 0.0)
    body.look(0.0, 0.0)
    if not (seen_wall.found and reach.found):
        return "failure"
    sign = side_sign(direction)
    front = near.distance if near.found else 0.0
    corners = [(front + depth, sign * reach.lateral) for depth in {0.0, max(0.0, width)}]
    gap = room_to_wall(seen_wall, corners, sign)
    if not math.isfinite(gap):
        return "failure"
    if gap <= wall_gap:
        return Outcome("reached", steps=0, gap=round(gap, 3))
    count = max(1, min(steps, math.floor(gap / step)))
    return Outcome("not_reached", steps=count, gap=round(gap, 3))
