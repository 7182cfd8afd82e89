"""Robot: what one humanoid can command and sense, and nothing about the world's poses."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pybullet as p

from hfsm_sim.base import Base, Chassis, Scanner, clamp
from hfsm_sim.battery import Battery
from hfsm_sim.body import ARMS, HEAD, NECK, RobotBody, drive_joint
from hfsm_sim.camera import CameraModel, camera_model, camera_spec, world_camera
from hfsm_sim.profile import MotionProfile
from hfsm_sim.raster import Rasteriser, Renderer

SETTLED_ANGLE, SETTLED_HEIGHT = 0.01, 0.002
# The humanoid's range finder sweeps at chest height, as a NAO's sonars sit: over a table standing
# on the floor (top 0.33 m), so it sees robots, walls and the legs of a lifted table.
SCAN_HEIGHT, SCAN_INNER = 0.40, 0.16

Vector = tuple[float, float, float]


def _to_body(v: np.ndarray, yaw: float) -> Vector:
    c, s = math.cos(yaw), math.sin(yaw)
    return (float(c * v[0] + s * v[1]), float(-s * v[0] + c * v[1]), float(v[2]))


@dataclass(frozen=True)
class ArmState:
    """Hand height above the floor (m), the commanded height, and whether they are there."""

    height: float
    target: float
    settled: bool


@dataclass(frozen=True)
class HandLoad:
    """What the arms feel of the load in the hands, in the body frame (forward, left, up):

    * `force` (N, summed over both hands): what the arm joints' currents tell. A table held
      still weighs ~10 N down on each of two carriers, and the carriers squeeze, stretch or
      shear it between them by tens of N when they are a few mm out of place.
    * `left`, `right` (m): each hand's give, how far the load has pulled it off the posture
      the arm holds (the joint encoders against their targets). Millimetres to ~1.5 cm while the
      carriers keep the table between them; it grows at walking speed when the table is stuck
      (a corner against a wall) and the robot walks on; at 5 cm the hand loses its grip.

    All zero when the hands hold nothing (a hand that grips nothing gives nothing)."""

    force: Vector
    left: Vector
    right: Vector

    @property
    def give(self) -> Vector:
        """The mean of the two hands' give (m): how the load pulls the pair of hands."""
        return (
            (self.left[0] + self.right[0]) / 2,
            (self.left[1] + self.right[1]) / 2,
            (self.left[2] + self.right[2]) / 2,
        )


class Robot(Base):
    """The humanoid: a base (see `Base`), a head with two cameras, and arms that lift.

    Created by `World`; behaviours never build one."""

    body_kind = "full"

    def __init__(self, cid: int, name: str, body: RobotBody, motion: MotionProfile,
                 rng: np.random.Generator, image_size: tuple[int, int],
                 holding: Callable[[], bool],
                 load: Callable[[], tuple[np.ndarray, np.ndarray]],
                 battery: Battery | None = None, *, cameras: Renderer | None = None,
                 scan_rng: np.random.Generator | None = None) -> None:
        g = body.geometry
        super().__init__(cid, name, Chassis(body.body, body.mocap, g.hover, g.base_max_force), motion,
                         rng, battery)
        self._body, self._g = body, g
        self._image_size = image_size
        self._cameras = cameras or Rasteriser(cid)
        self._holding = holding
        self._load = load
        self._head_target = (0.0, 0.0)
        self._arm_target = motion.arm_low
        self._scanner = Scanner(SCAN_HEIGHT, SCAN_INNER, scan_rng or np.random.default_rng(0))

    # head
    def set_head(self, yaw: float, pitch: float) -> None:
        """Head joint targets in radians (yaw left positive, pitch down positive), clamped."""
        if self.failed:
            return
        m = self.profile
        self._head_target = (clamp(yaw, -m.head_yaw_max, m.head_yaw_max),
                             clamp(pitch, m.head_pitch_min, m.head_pitch_max))
        drive_joint(self._cid, self._body.body, NECK, self._head_target[0], m.head_speed)
        drive_joint(self._cid, self._body.body, HEAD, self._head_target[1], m.head_speed)

    def head(self) -> tuple[float, float]:
        """Current head joint angles (yaw, pitch) in radians."""
        states = p.getJointStates(self._body.body, [NECK, HEAD], physicsClientId=self._cid)
        return (float(states[0][0]), float(states[1][0]))

    def head_settled(self) -> bool:
        yaw, pitch = self.head()
        return (abs(yaw - self._head_target[0]) < SETTLED_ANGLE
                and abs(pitch - self._head_target[1]) < SETTLED_ANGLE)

    # cameras
    def camera_model(self, camera: str = "forward") -> CameraModel:
        """Intrinsics, mounting (height, pitch, yaw incl. the head joints) in the body frame, and
        the body's pose by odometry now."""
        yaw, pitch = self.head()
        return camera_model(camera_spec(camera), self._g, self._image_size, yaw, pitch,
                            self.odometry())

    def image(self, camera: str = "forward") -> np.ndarray:
        """Render this camera now: H x W x 3 uint8 RGB."""
        rgb, _ = self._render(camera, segmentation=False)
        return rgb

    def _render(self, camera: str, *, segmentation: bool) -> tuple[np.ndarray, np.ndarray | None]:
        pos, orn = p.getBasePositionAndOrientation(self._body.body, physicsClientId=self._cid)
        view = world_camera(self.camera_model(camera), pos, orn)
        return self._cameras.render(view, segmentation=segmentation)

    # arms
    def arms_lower(self) -> None:
        """Lower the hands to the lowest (carry-ready) height; lands a held table."""
        self.arms_lift(self.profile.arm_low)

    def arms_lift(self, height: float) -> None:
        """Move the hands to `height` metres above the floor (clamped to the arm range)."""
        if self.failed:
            return
        m = self.profile
        self._arm_target = clamp(height, m.arm_low, m.arm_high)
        drive_joint(self._cid, self._body.body, ARMS, self._arm_target - self._g.hover,
                    m.arm_speed)

    def arms_state(self) -> ArmState:
        q = p.getJointState(self._body.body, ARMS, physicsClientId=self._cid)[0]
        height = float(q) + self._g.hover
        return ArmState(height, self._arm_target, abs(height - self._arm_target) < SETTLED_HEIGHT)

    def holding(self) -> bool:
        """True while the hands carry a load (the table gripped from below)."""
        return self._holding()

    def hand_load(self) -> HandLoad:
        """The load on the hands, in the body frame (see `HandLoad`); the force is low-passed
        over ~0.05 s. Zero when not holding."""
        force, give = self._load()
        yaw = self._true_pose()[2]
        return HandLoad(_to_body(force, yaw), _to_body(give[0], yaw), _to_body(give[1], yaw))

    # called by World and Lifting
    def _arms_active(self) -> bool:
        return self._arm_target > self.profile.arm_low + 1e-6

    def _arms_lowering(self) -> bool:
        return self._arm_target < self.arms_state().height - SETTLED_HEIGHT
