"""Align to middle of table (Figure 9, Behaviour 2): look both ways, walk toward the longer side."""

from __future__ import annotations

import math

from behaviours.body import Body
from behaviours.carry.sensing import edge, extent
from hfsm.primitive import Context, Outcome, primitive


def relative_difference(left: float, right: float) -> float:
    """|left - right| relative to the longer side (0 when equal, 1 when one side is 0)."""
    longer = max(left, right)
    return abs(left - right) / longer if longer > 0 else 0.0


@primitive(outcomes=["aligned", "lost"], failures=["lost"], outputs=["difference"], world="sim")
def align_to_middle_of_table(
    ctx: Context,
    *,
    difference: float = 0.20,
    angle_tolerance: float = 20.0,
    step: float = 0.05,
    look_yaw: float = 1.3,
    look_pitch: float = 0.45,
    edge_pitch: float = 0.5,
    rounds: int = 12,
) -> str | Outcome:
    """Behaviour 2: look left and right to determine which side is the longest; while the
    relative difference of the lengths exceeds `difference` (0.20: the paper's 20 %): align
    the body parallel to the table (turn when off by more than `angle_tolerance` degrees),
    walk sideways toward the longer side for at most `step` m, look again. Each round first
    looks down at the near edge: to turn parallel, and to measure the lengths along the edge.

    `lost` when the table is not seen, or after `rounds` rounds without success.
    Output `difference`: the last relative difference measured.
    """
    body = Body(ctx)
    for _ in range(rounds):
        seen = edge(body, edge_pitch)
        if not seen.found:
            return "lost"
        turn = seen.turn
        if abs(turn) > math.radians(angle_tolerance):
            body.turn(turn)
            turn = 0.0
        left = extent(body, "left", look_yaw, look_pitch, turn)
        right = extent(body, "right", look_yaw, look_pitch, turn)
        if not (left.found and right.found):
            return "lost"
        rel = relative_difference(left.lateral, right.lateral)
        if rel <= difference:
            body.look(0.0, 0.0)
            return Outcome("aligned", difference=round(rel, 3))
        shift = min(step, abs(left.lateral - right.lateral) / 2)
        body.crab(math.copysign(shift, left.lateral - right.lateral))
    return "lost"
