"""Blocking moves of one robot, for primitives: each call returns when the move is over.

A move holds a velocity for the time the commanded span takes at the robot's speed, then stops;
if the interpreter cancels the primitive meanwhile, `Cancelled` comes out of the wait and the
`finally` stops the robot. Nothing here reads the simulator's ground truth.
"""

from __future__ import annotations

import math

import numpy as np

from hfsm.primitive import Context
from hfsm_sim import CameraModel, Robot
from hfsm_sim.profile import MotionProfile


class Body:
    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx
        self.robot: Robot = ctx.robot
        self.motion: MotionProfile = self.robot.profile  # its own speeds: timed moves cover their spans

    def _hold(self, forward: float, sideways: float, turn: float, seconds: float) -> None:
        if seconds <= 0:
            return
        self.robot.set_velocity(forward, sideways, turn)
        try:
            self.ctx.wait(seconds)
        finally:
            self.robot.stop()

    def walk(self, distance: float) -> None:
        """Forward (negative: backward) by about `distance` metres."""
        speed = self.motion.forward_max if distance >= 0 else self.motion.backward_max
        self._hold(math.copysign(speed, distance), 0.0, 0.0, abs(distance) / speed)

    def crab(self, distance: float) -> None:
        """Sideways by about `distance` metres, left positive."""
        speed = self.motion.sideways_max
        self._hold(0.0, math.copysign(speed, distance), 0.0, abs(distance) / speed)

    def turn(self, angle: float) -> None:
        """On the spot by about `angle` radians, left (counter-clockwise) positive."""
        speed = self.motion.turn_max
        self._hold(0.0, 0.0, math.copysign(speed, angle), abs(angle) / speed)

    def drive(self, forward: float, sideways: float, turn: float, seconds: float) -> None:
        """Hold a velocity (m/s, m/s, rad/s; clamped by the robot) for a span, then stop."""
        self._hold(forward, sideways, turn, seconds)

    def look(self, yaw: float, pitch: float, timeout: float = 3.0) -> None:
        """Turn the head (radians; pitch positive looks down) and wait until it is still."""
        self.robot.set_head(yaw, pitch)
        self.ctx.wait()
        self.ctx.wait_until(self.robot.head_settled, timeout)

    def image(self, camera: str = "forward") -> np.ndarray:
        return self.robot.image(camera)

    def camera(self, camera: str = "forward") -> CameraModel:
        return self.robot.camera_model(camera)

    def odometry(self) -> tuple[float, float, float]:
        return self.robot.odometry()

    def arms(self, height: float | None, timeout: float = 10.0) -> bool:
        """Raise the hands to `height` metres above the floor (None: lower them); True when there."""
        if height is None:
            self.robot.arms_lower()
        else:
            self.robot.arms_lift(height)
        self.ctx.wait()
        return self.ctx.wait_until(lambda: self.robot.arms_state().settled, timeout)
