"""go_to: drive to a point (plus a formation offset) by odometry, tick by tick; stop.

The robot steers by what it senses: its odometry, the points of others it was told over the
radio (`avoid`), and, with `look`, what its proximity sensor senses (light bodies); never the simulator's
poses.
"""

from __future__ import annotations

import math
from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import odom_to_body, wrap
from hfsm_behaviours.drive.avoid import Detour, Sensing, dodge

Point = tuple[float, float]
BRAKE, CREEP = 2.0, 0.05


def goal_point(start: Point, x: float, y: float, offset: list[float], frame: str) -> Point:
    """The point `(x, y)` plus `offset` [dx, dy]: in the odometry frame (`frame: odometry`), or in
    the frame of travel (`frame: travel`, x along the line from `start` to the point, y to its
    left), so that robots given the same point and different offsets keep a formation's shape."""
    dx, dy = (float(offset[0]), float(offset[1])) if offset else (0.0, 0.0)
    if frame == "travel":
        heading = math.atan2(y - start[1], x - start[0])
        c, s = math.cos(heading), math.sin(heading)
        dx, dy = c * dx - s * dy, s * dx + c * dy
    elif frame != "odometry":
        raise ValueError(f"frame is 'odometry' or 'travel', not {frame!r}")
    return (x + dx, y + dy)


def heading(here: tuple[float, float, float], goal: Point, speed: float, avoid: list[Point],
            clearance: float) -> Point:
    """Room-frame velocity towards the goal, braking near it (BRAKE m/s per metre left, never below
    CREEP), pushed away from points nearer than `clearance`."""
    gx, gy = goal[0] - here[0], goal[1] - here[1]
    dist = math.hypot(gx, gy)
    pace = min(speed, BRAKE * dist + CREEP)
    vx, vy = (gx / dist * pace, gy / dist * pace) if dist > 1e-9 else (0.0, 0.0)
    for ox, oy in avoid:
        rx, ry = here[0] - ox, here[1] - oy
        gap = math.hypot(rx, ry)
        if 1e-9 < gap < clearance:
            push = speed * (clearance - gap) / clearance * 2.0
            vx, vy = vx + rx / gap * push, vy + ry / gap * push
    return (vx, vy)


def body_velocity(here: tuple[float, float, float], velocity: Point, speed: float
                  ) -> tuple[float, float, float]:
    """A room-frame velocity as the body's (forward, left, turn), turning to face the way it goes."""
    vx, vy = velocity
    forward, left = odom_to_body((0.0, 0.0, here[2]), (vx, vy))
    turn = wrap(math.atan2(vy, vx) - here[2]) * 2.0 if math.hypot(vx, vy) > 0.05 * speed else 0.0
    return forward, left, turn


def _points(avoid: list[Any]) -> list[Point]:
    return [(float(p[0]), float(p[1])) if isinstance(p, list | tuple) else (float(p["x"]), float(p["y"]))
            for p in avoid]


@primitive(outcomes=["arrived", "timeout"], outputs=["x", "y"], world="sim")
def go_to(ctx: Context, *, x: float, y: float, offset: list[float] | None = None, frame: str = "odometry",
          relative: bool = False, tolerance: float = 0.1, speed: float = 0.0,
          avoid: list[Any] | None = None, clearance: float = 0.6, look: float = 0.0,
          timeout: float = 120.0) -> Outcome:
    """Drive to the point (x, y) of the odometry frame (`relative`: that far from where it is) plus a
    formation `offset` [dx, dy] (see `frame`), at `speed` m/s (0: the body's top speed), keeping
    `clearance` metres from the `avoid` points ([x, y] or {x, y}: where others said they are) and,
    when `look` > 0, from what its proximity sensor senses within `look` metres, steering round
    it (`avoid.Detour`); `arrived` within `tolerance` metres."""
    robot = ctx.robot
    start = robot.odometry()
    if relative:
        x, y = start[0] + x, start[1] + y
    goal = goal_point(start[:2], x, y, offset or [], frame)
    top = robot.profile.forward_max
    pace = min(speed, top) if speed > 0 else top
    others = _points(avoid or [])
    deadline = ctx.time + timeout
    way_out = Detour()
    sensing = Sensing(robot, look)
    try:
        while True:
            here = robot.odometry()
            if math.hypot(goal[0] - here[0], goal[1] - here[1]) <= tolerance:
                return Outcome("arrived", x=round(here[0], 6), y=round(here[1], 6))
            if ctx.time >= deadline:
                return Outcome("timeout", x=round(here[0], 6), y=round(here[1], 6))
            velocity = heading(here, goal, pace, others, clearance)
            seen = sensing.seen(ctx.time, here)
            if seen:
                left = math.hypot(goal[0] - here[0], goal[1] - here[1])
                velocity = way_out.steer(ctx.time, velocity, seen, clearance, pace, left)
            robot.set_velocity(*body_velocity(here, velocity, pace))
            ctx.wait()
    finally:
        robot.stop()


@primitive(outcomes=["timeout"], world="sim")
def hold(ctx: Context, *, x: float, y: float, tolerance: float = 0.1, look: float = 1.0,
         clearance: float = 0.3, timeout: float = 3600.0) -> Outcome:
    """Keep to the point (x, y) of the odometry frame while waiting (a background region beside a
    barrier): go back to it when farther than `tolerance`, and make way for what the proximity
    sensor senses nearer than `clearance` (slide aside, as `go_to` does), so that a robot waiting
    in a crowd is no wall to one passing through. Ends `timeout` after `timeout` seconds."""
    robot = ctx.robot
    pace = robot.profile.forward_max
    deadline = ctx.time + timeout
    sensing = Sensing(robot, look)
    try:
        while ctx.time < deadline:
            here = robot.odometry()
            far = math.hypot(x - here[0], y - here[1]) > tolerance
            velocity = heading(here, (x, y), pace, [], clearance) if far else (0.0, 0.0)
            seen = [p for p in sensing.seen(ctx.time, here) if math.hypot(*p) < clearance]
            if seen:
                velocity = dodge(velocity, seen, clearance, pace)
            if far or seen:
                robot.set_velocity(*body_velocity(here, velocity, pace))
            else:
                robot.stop()
            ctx.wait()
        return Outcome("timeout")
    finally:
        robot.stop()


@primitive(outcomes=["done"], world="sim")
def stop(ctx: Context) -> str:
    """Stop at once (velocity zero), and wait one tick for the body to settle its command."""
    ctx.robot.stop()
    ctx.wait()
    return "done"
