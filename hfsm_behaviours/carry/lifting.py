"""Lift and land the table: the arms' part of Synchronised lift table and Land table."""

from __future__ import annotations

from hfsm.primitive import Context, primitive
from hfsm_behaviours.body import Body


@primitive(outcomes=["lifted", "failure"], world="sim")
def lift_table(ctx: Context, *, height: float = 0.42, timeout: float = 6.0) -> str:
    """Raise the hands to `height` m above the floor under the table's edge; `lifted` when
    they are there and carry the load, `failure` when they rose but hold nothing."""
    body = Body(ctx)
    settled = body.arms(height, timeout)
    return "lifted" if settled and ctx.robot.holding() else "failure"


@primitive(outcomes=["landed", "failure"], world="sim")
def land_table(ctx: Context, *, timeout: float = 6.0) -> str:
    """Land table (Figure 3): lower the hands; the table's feet touch the floor and the
    hands come free. `failure` if the hands still carry a load when they are down."""
    body = Body(ctx)
    settled = body.arms(None, timeout)
    return "landed" if settled and not ctx.robot.holding() else "failure"
