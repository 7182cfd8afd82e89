"""Small step sideways (Figure 3): a few crab steps with the table held."""

from __future__ import annotations

from behaviours.body import Body
from behaviours.carry.sensing import side_sign
from hfsm.primitive import Context, primitive


@primitive(outcomes=["stepped", "dropped"], failures=["dropped"], world="sim")
def small_step_sideways(
    ctx: Context,
    *,
    direction: str,
    steps: int = 10,
    step: float = 0.05,
    pause: float = 0.2,
) -> str:
    """Take `steps` sideways steps of `step` m toward `direction` ('left' or 'right', in the
    robot's own frame), pausing `pause` s after each. The two robots start together (the lift
    handshake) and take the same steps, so they keep the table between them. `dropped` as
    soon as the hands no longer carry the table."""
    body = Body(ctx)
    sign = side_sign(direction)
    for _ in range(steps):
        if not ctx.robot.holding():
            return "dropped"
        body.crab(sign * step)
        ctx.wait(pause)
    return "stepped" if ctx.robot.holding() else "dropped"
