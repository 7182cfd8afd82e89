"""go_along: drive through a list of waypoints of the odometry frame, one after the other (a
planned walk, hfsm_behaviours.room.walks), as go_to drives to one."""

from __future__ import annotations

import math
from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import wrap
from hfsm_behaviours.drive.avoid import Detour, Sensing
from hfsm_behaviours.drive.goto import body_velocity, heading
from hfsm_behaviours.drive.localise import Framed

FACED = 0.1  # radians: facing the point


@primitive(outcomes=["arrived", "timeout"], outputs=["x", "y"], world="sim")
def go_along(ctx: Context, *, points: list[Any], tolerance: float = 0.3, last: float = 0.15,
             speed: float = 0.0, face: list[Any] | None = None, look: float = 0.0,
             clearance: float = 0.45, timeout: float = 120.0) -> Outcome:
    """Drive through `points` ([x, y] of the odometry frame) in order at `speed` m/s (0: the body's
    top speed): on to the next within `tolerance` m of one, `arrived` within `last` m of the last,
    then turned on the spot to `face` that point ([x, y], if given). With `look` > 0 it keeps
    `clearance` metres from what it senses within `look` metres (robots; see `avoid.sensed`),
    sliding past and steering round it as go_to does."""
    robot = ctx.robot
    top = robot.profile.forward_max
    pace = min(speed, top) if speed > 0 else top
    goals = [(float(p[0]), float(p[1])) for p in points]
    deadline = ctx.time + timeout
    sensing = Sensing(robot, look)
    try:
        for k, goal in enumerate(goals):
            near = last if k == len(goals) - 1 else tolerance
            way_out = Detour()
            while True:
                here = robot.odometry()
                if math.hypot(goal[0] - here[0], goal[1] - here[1]) <= near:
                    break
                if ctx.time >= deadline:
                    return Outcome("timeout", x=round(here[0], 6), y=round(here[1], 6))
                velocity = heading(here, goal, pace, [], 0.0)
                seen = sensing.seen(ctx.time, here)
                if seen:
                    left = math.hypot(goal[0] - here[0], goal[1] - here[1])
                    velocity = way_out.steer(ctx.time, velocity, seen, clearance, pace, left)
                robot.set_velocity(*body_velocity(here, velocity, pace))
                ctx.wait()
        while face:
            here = robot.odometry()
            turn = wrap(math.atan2(float(face[1]) - here[1], float(face[0]) - here[0]) - here[2])
            if abs(turn) <= FACED or ctx.time >= deadline:
                break
            robot.set_velocity(0.0, 0.0, max(-1.0, min(1.0, 2.0 * turn)))
            ctx.wait()
        here = robot.odometry()
        return Outcome("arrived", x=round(here[0], 6), y=round(here[1], 6))
    finally:
        robot.stop()


@primitive(outcomes=["read"], outputs=["pose"], world="sim")
def odometry_pose(ctx: Context) -> Outcome:
    """Where the robot is by its odometry now, {x, y: metres, yaw: degrees} (as in.pose)."""
    x, y, yaw = ctx.robot.odometry()
    return Outcome("read", pose={"x": round(x, 4), "y": round(y, 4), "yaw": round(math.degrees(yaw), 2)})


@primitive(outcomes=["localising", "unable"], world="sim")
def localise(ctx: Context, *, start: dict[str, Any], room: dict[str, Any]) -> Outcome:
    """From now on this humanoid's odometry (in.pose, still in its own start frame) and its cameras'
    poses are corrected against the walls of the `room` ({width, depth}: metres, centred on 0) by
    its range finder, every second: its start frame is where it was told it started (`start`: {x, y:
    metres, yaw: degrees} in the room's frame). `unable` for a body without it (a light body's
    odometry is corrected so always)."""
    robot = ctx.robot
    if not isinstance(robot, Framed):
        return Outcome("unable")
    robot.localise((float(start["x"]), float(start["y"]), math.radians(float(start["yaw"]))),
                   (float(room["width"]), float(room["depth"])))
    return Outcome("localising")
