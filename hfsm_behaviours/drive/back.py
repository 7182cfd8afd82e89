"""back_away: step straight back from what the robot faces (a table it just put down), by odometry."""

from __future__ import annotations

import math

from hfsm.primitive import Context, Outcome, primitive


@primitive(outcomes=["done"], world="sim")
def back_away(ctx: Context, *, distance: float = 0.5, speed: float = 0.1, timeout: float = 15.0) -> Outcome:
    """Walk backwards, without turning, until `distance` m from where it began (or `timeout` s), then
    stop: a robot leaving a table it held clears its hands of the edge before it turns away."""
    robot = ctx.robot
    x0, y0, _ = robot.odometry()
    deadline = ctx.time + timeout
    try:
        while ctx.time < deadline:
            x, y, _ = robot.odometry()
            if math.hypot(x - x0, y - y0) >= distance:
                break
            robot.set_velocity(-abs(speed), 0.0, 0.0)
            ctx.wait()
    finally:
        robot.stop()
    return Outcome("done")
