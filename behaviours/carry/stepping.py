"""Small step sideways (Figure 3): a few crab steps with the table held, stopping as soon as
the arms feel the table resist (a corner against a wall), before the grip gives."""

from __future__ import annotations

from behaviours.body import Body
from behaviours.carry.sensing import side_sign
from hfsm.primitive import Context, Outcome, primitive


@primitive(outcomes=["stepped", "blocked", "dropped"], failures=["dropped"], outputs=["give"],
           world="sim")
def small_step_sideways(
    ctx: Context,
    *,
    direction: str,
    steps: int = 10,
    step: float = 0.05,
    pause: float = 0.2,
    max_give: float = 0.02,
) -> str | Outcome:
    """Take `steps` sideways steps of `step` m toward `direction` ('left' or 'right', in the
    robot's own frame), pausing `pause` s after each. The two robots start together (the lift
    handshake) and take the same steps, so they keep the table between them.

    Like an insect, the robot feels the load on its arms (`hand_load`): while it walks, a hand
    pulled back against the walk by more than `max_give` m means the table does not follow (a
    corner against a wall); stop at once, `blocked` (the grip is lost at 5 cm). `give` is the
    largest such pull felt (m). `dropped` as soon as the hands no longer carry the table."""
    body = Body(ctx)
    sign = side_sign(direction)
    felt = 0.0

    def resisted() -> bool:
        nonlocal felt
        load = ctx.robot.hand_load()
        felt = max(felt, -sign * float(load.left[1]), -sign * float(load.right[1]))
        return felt > max_give

    for _ in range(steps):
        if not ctx.robot.holding():
            return "dropped"
        if body.crab_until(sign * step, resisted):
            return Outcome("blocked", give=round(felt, 3))
        ctx.wait(pause)
    return Outcome("stepped", give=round(felt, 3)) if ctx.robot.holding() else "dropped"
