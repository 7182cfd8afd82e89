"""Re-centre to middle of table (Figure 3): stand square to the near long edge, hands under it."""

from __future__ import annotations

import math

from hfsm.primitive import Context, primitive
from hfsm_behaviours.body import Body
from hfsm_behaviours.carry.sensing import edge


@primitive(outcomes=["centred", "lost"], failures=["lost"], world="sim")
def recentre_to_middle_of_table(
    ctx: Context,
    *,
    grip_distance: float = 0.09,
    distance_tolerance: float = 0.02,
    angle_tolerance: float = 2.0,
    pitch: float = 0.5,
    tries: int = 4,
) -> str:
    """Square up to the table's near long edge at grip distance, by the down camera.

    Look down at the edge; turn until the shoulders are parallel to it within
    `angle_tolerance` degrees, then step forward or back until the edge is `grip_distance`
    (m) ahead of the body centre, within `distance_tolerance`, so that the hands are under it.
    `lost` if the edge is not seen or the body is not square after `tries` looks.
    """
    body = Body(ctx)
    for _ in range(tries):
        seen = edge(body, pitch)
        if not seen.found:
            return "lost"
        if abs(seen.turn) > math.radians(angle_tolerance):
            body.turn(seen.turn)
            continue
        error = seen.distance - grip_distance
        if abs(error) <= distance_tolerance:
            return "centred"
        body.walk(error)
    return "lost"
