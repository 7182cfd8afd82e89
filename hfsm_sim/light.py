"""Light robots: a camera-less cylinder (drawn as boxes) that drives by velocity commands, for
teams of tens (the TARARC allocation experiments). No head, no arms, no cameras: it senses its
odometry (in the room's frame, from the start pose the scenario tells it), its battery and bumps,
hears the radio, has a proximity sensor (`nearby`), as the paper's Player/Stage robots have
lasers, to steer round what is near, and a laser range finder (`scan`) to see the walls by. It
collides with walls, tables and other robots like the humanoid does."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pybullet as p

from hfsm_sim.base import Base, Chassis, Pose, Scanner
from hfsm_sim.battery import Battery
from hfsm_sim.profile import MotionProfile


@dataclass(frozen=True)
class LightGeometry:
    radius: float = 0.15
    height: float = 0.30
    mass: float = 3.0
    hover: float = 0.003
    max_force: float = 120.0


LIGHT_BODY = LightGeometry()
FLOOR_TOP = 0.05  # a body whose bounding box ends below this height is the floor
SCAN_HEIGHT = 0.2  # metres above the floor the range finder's beams sweep
LIGHT_MOTION = MotionProfile(forward_max=0.5, backward_max=0.5, sideways_max=0.5, turn_max=2.0)


def light_motion(speed: float | None) -> MotionProfile:
    """The light body's limits, with its top speed (any direction) set to `speed` m/s."""
    if speed is None:
        return LIGHT_MOTION
    return replace(LIGHT_MOTION, forward_max=speed, backward_max=speed, sideways_max=speed)


def build_light(cid: int, g: LightGeometry, colour: tuple[float, float, float], pose: Pose) -> Chassis:
    col = p.createCollisionShape(p.GEOM_CYLINDER, radius=g.radius, height=g.height,
                                 collisionFramePosition=[0, 0, g.height / 2], physicsClientId=cid)
    # Seen as boxes (two squares a quarter-turn apart, and a dark nose), as every other body of the
    # world is: the robots' cameras draw boxes.
    side, half_h = g.radius * 0.85, g.height / 2
    turned = p.getQuaternionFromEuler([0.0, 0.0, math.pi / 4])
    vis = p.createVisualShapeArray(
        [p.GEOM_BOX] * 3,
        halfExtents=[[side, side, half_h], [side, side, half_h], [g.radius * 0.45, 0.02, 0.01]],
        visualFramePositions=[[0, 0, half_h], [0, 0, half_h], [g.radius * 0.5, 0, g.height + 0.01]],
        visualFrameOrientations=[[0, 0, 0, 1], list(turned), [0, 0, 0, 1]],
        rgbaColors=[[*colour, 1.0], [*colour, 1.0], [0.1, 0.1, 0.1, 1.0]], physicsClientId=cid)
    x, y, yaw = pose
    orn = p.getQuaternionFromEuler([0.0, 0.0, yaw])
    body = int(p.createMultiBody(g.mass, col, vis, basePosition=[x, y, g.hover], baseOrientation=orn,
                                 physicsClientId=cid))
    mocap = p.createConstraint(body, -1, -1, -1, p.JOINT_FIXED, [0, 0, 0], [0, 0, 0],
                               [x, y, g.hover], childFrameOrientation=orn, physicsClientId=cid)
    p.changeConstraint(mocap, maxForce=g.max_force, physicsClientId=cid)
    return Chassis(body=body, mocap=int(mocap), hover=g.hover, max_force=g.max_force)


class LightRobot(Base):
    """A light body: see `Base` for what it commands and senses. Its odometry starts at the start
    pose the scenario gives it (room frame, degrees turned to radians), not at the true (jittered)
    one: the jitter is its error of localisation."""

    body_kind = "light"

    def __init__(self, cid: int, name: str, chassis: Chassis, motion: MotionProfile,
                 rng: np.random.Generator, told_start: Pose, battery: Battery | None = None) -> None:
        super().__init__(cid, name, chassis, motion, rng, battery, told_start)
        noise = np.random.default_rng(rng.integers(2**32))
        self._scanner = Scanner(SCAN_HEIGHT, LIGHT_BODY.radius + 0.01, noise)

    def holding(self) -> bool:
        """A light body has no hands."""
        return False

    def nearby(self, reach: float) -> list[tuple[float, float]]:
        """A proximity sensor, as the paper's Player/Stage robots have lasers and sonars: for every
        thing (robot, wall, table) within `reach` metres of the body's side, its nearest point, as
        (forward, left) metres from the body's centre, nearest thing first. A failed body senses
        nothing."""
        if self.failed or reach <= 0.0:
            return []
        x, y, yaw = self._true_pose()
        span = LIGHT_BODY.radius + reach
        low, high = [x - span, y - span, 0.05], [x + span, y + span, LIGHT_BODY.height]
        overlapping = p.getOverlappingObjects(low, high, physicsClientId=self._cid) or ()
        found: list[tuple[float, float, float]] = []
        for other in sorted({body for body, _ in overlapping} - {self._chassis.body}):
            if p.getAABB(other, physicsClientId=self._cid)[1][2] < FLOOR_TOP:
                continue  # the floor, which the body stands on
            points = p.getClosestPoints(self._chassis.body, other, reach, physicsClientId=self._cid)
            if points:
                nearest = min(points, key=lambda q: q[8])
                found.append((nearest[8], nearest[6][0] - x, nearest[6][1] - y))
        c, s = math.cos(yaw), math.sin(yaw)
        return [(c * dx + s * dy, -s * dx + c * dy) for _, dx, dy in sorted(found)]

    # Teams of tens: the leash is kept once per control tick, not every physics step (one pybullet
    # call a step instead of two), so a blocked light robot may lead its body by a tick's travel.
    def _before_advance(self, dt: float) -> None:
        if self._cmd != (0.0, 0.0, 0.0):
            self._target = self._leashed(self._target, dt)
            self._push_target()

    def _unwind(self) -> None:
        """Not on every new command: steered by a new velocity each tick, it would lose its lead each
        tick and crawl; `_before_advance` keeps the lead within the leash instead."""

    def _pre_step(self, dt: float) -> None:
        if self._cmd != (0.0, 0.0, 0.0):
            self._target = self._ahead(dt)
            self._push_target()


def told_pose(x: float, y: float, yaw_degrees: float) -> Pose:
    return (x, y, math.radians(yaw_degrees))
