"""Small step sideways (Figure 3): a few crab steps with the table held.

The robot feels the table stop following (a corner against a wall) on its arms, like an insect:
`machines/step_together.yaml` watches each hand's give (`in.hand_give_left`, `in.hand_give_right`)
and whether the hands still hold (`in.holding`) while this primitive walks, and stops it."""

from __future__ import annotations

from hfsm.primitive import Context, primitive
from hfsm_behaviours.body import Body
from hfsm_behaviours.carry.sensing import side_sign


@primitive(outcomes=["stepped"], world="sim")
def small_step_sideways(
    ctx: Context, *, direction: str, steps: int = 10, step: float = 0.05, pause: float = 0.2
) -> str:
    """Take `steps` sideways steps of `step` m toward `direction` ('left' or 'right', in the
    robot's own frame), pausing `pause` s after each. The two robots start together (the lift
    handshake) and take the same steps, so they keep the table between them."""
    body = Body(ctx)
    sign = side_sign(direction)
    for _ in range(steps):
        body.crab(sign * step)
        ctx.wait(pause)
    return "stepped"
