"""The steps of Align to middle of table (Figure 9, Behaviour 2); the loop is the machine
machines/align_to_middle_of_table.yaml."""

from __future__ import annotations

import math

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.body import Body
from hfsm_behaviours.carry.sensing import edge, extent


@primitive(outcomes=["measured", "lost"], failures=["lost"], outputs=["left", "right"], world="sim")
def look_left_and_right(
    ctx: Context, *, look_yaw: float = 1.3, look_pitch: float = 0.45, edge_pitch: float = 0.5
) -> str | Outcome:
    """Look left and right along the near long edge: how far the table reaches each way (m).

    First looks down at the edge, so that a body not quite parallel is allowed for; ends looking
    ahead. `lost` when the table is not seen.
    """
    body = Body(ctx)
    seen = edge(body, edge_pitch)
    if not seen.found:
        return "lost"
    left = extent(body, "left", look_yaw, look_pitch, seen.turn)
    right = extent(body, "right", look_yaw, look_pitch, seen.turn)
    body.look(0.0, 0.0)
    if not (left.found and right.found):
        return "lost"
    return Outcome("measured", left=round(left.lateral, 4), right=round(right.lateral, 4))


@primitive(outcomes=["parallel", "lost"], failures=["lost"], world="sim")
def align_body_parallel(ctx: Context, *, angle_tolerance: float = 20.0, edge_pitch: float = 0.5) -> str:
    """Turn the shoulders parallel to the near long edge when off by more than `angle_tolerance`
    degrees (seen by the down camera). `lost` when the edge is not seen."""
    body = Body(ctx)
    seen = edge(body, edge_pitch)
    if not seen.found:
        return "lost"
    if abs(seen.turn) > math.radians(angle_tolerance):
        body.turn(seen.turn)
    return "parallel"


@primitive(outcomes=["done"], world="sim")
def walk_sideways(ctx: Context, *, distance: float) -> str:
    """Crab sideways about `distance` m, left positive."""
    Body(ctx).crab(distance)
    return "done"
