"""What every robot body shares: a base dragged by a mocap constraint at commanded velocities,
odometry, a battery, bumps and failing. `hfsm_sim.robot.Robot` (the humanoid) and `hfsm_sim.light.LightRobot`
(a camera-less cylinder) build on it."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import pybullet as p

from hfsm_sim.battery import Battery
from hfsm_sim.body import yaw_of
from hfsm_sim.odometry import Odometry, wrap
from hfsm_sim.profile import MotionProfile

LEASH_XY, LEASH_YAW = 0.02, 0.1
SCAN_NOISE = 0.01  # metres, 1 sigma, on each range (a Hokuyo's is ~1-3 cm)
UNWIND_XY, UNWIND_YAW = 0.01, 0.05

Pose = tuple[float, float, float]


def clamp(value: float, low: float, high: float) -> float:
    return max(low, min(high, value))


@functools.cache
def _turns(beams: int) -> np.ndarray:
    """Beam k's angle from straight ahead, k/beams of a turn (kept: a scan's beams are always the same)."""
    turns = np.arange(beams) * (2 * math.pi / beams)
    turns.flags.writeable = False
    return turns


@dataclass(frozen=True)
class Chassis:
    """A body's base in pybullet: the body, the mocap constraint dragging it, its height over the
    floor and the constraint's force."""

    body: int
    mocap: int
    hover: float
    max_force: float


@dataclass(frozen=True)
class Scanner:
    """A body's laser range finder: the height its beams sweep, how far from the body's centre they
    start (outside its own body) and its own seeded noise."""

    height: float
    inner: float
    rng: np.random.Generator


class Base:
    """Commands are held until changed; all readings are what the robot itself could sense."""

    def __init__(self, cid: int, name: str, chassis: Chassis, motion: MotionProfile,
                 rng: np.random.Generator, battery: Battery | None = None,
                 told_start: Pose | None = None) -> None:
        self.name = name
        self.profile = motion
        self._cid, self._chassis = cid, chassis
        self._cmd = (0.0, 0.0, 0.0)
        pose = self._true_pose()
        self._target = pose
        self._start_xy = pose[:2]
        self._odometry = Odometry(rng, pose, told_start)
        self._bumped = False
        self._battery = battery
        self._last_xy = pose[:2]
        self.failed = False
        self._scanner: Scanner | None = None

    def set_velocity(self, forward: float, sideways: float, turn: float) -> None:
        """Walk velocity in the body frame (m/s forward, m/s to the left, rad/s counter-
        clockwise), clamped to the profile and held until changed."""
        if self.failed:
            return
        m = self.profile
        cmd = (clamp(forward, -m.backward_max, m.forward_max),
               clamp(sideways, -m.sideways_max, m.sideways_max),
               clamp(turn, -m.turn_max, m.turn_max))
        if cmd != self._cmd:
            self._cmd = cmd
            self._unwind()

    def stop(self) -> None:
        self.set_velocity(0.0, 0.0, 0.0)

    def velocity(self) -> tuple[float, float, float]:
        """The commanded (clamped) velocity."""
        return self._cmd

    def odometry(self) -> Pose:
        """(x, y, yaw) by dead reckoning with seeded drift: in the robot's own start frame, or in
        the room's frame from the start pose it was told (light bodies)."""
        return self._odometry.pose()

    def battery(self) -> float:
        """The battery's charge, 0 (empty) to 1 (full); 1 when the scenario models no battery."""
        return 1.0 if self._battery is None else self._battery.level

    def battery_empty(self) -> bool:
        return self._battery is not None and self._battery.empty

    def bumped(self) -> bool:
        """True if the body touched something during the last `World.advance`."""
        return self._bumped

    def scan(self, beams: int, reach: float) -> list[float]:
        """A laser range finder sweeping the full turn at its height: `beams` ranges in metres from the
        body's centre, beam k at k/beams of a turn counter-clockwise from straight ahead, each with
        seeded noise; `reach` where a beam hits nothing within `reach`. It sees whatever stands at its
        height alike (ray casts against the world). A failed body, or one with no range finder,
        senses nothing."""
        scanner = self._scanner
        if self.failed or beams <= 0 or scanner is None:
            return []
        x, y, yaw = self._true_pose()
        inner = scanner.inner
        angles = yaw + _turns(beams)
        c, s = np.cos(angles), np.sin(angles)
        height = np.full(beams, scanner.height)
        starts = np.stack([x + c * inner, y + s * inner, height], axis=1).tolist()
        ends = np.stack([x + c * reach, y + s * reach, height], axis=1).tolist()
        ids, _, fractions, *_ = zip(*p.rayTestBatch(starts, ends, numThreads=1, physicsClientId=self._cid),
                                    strict=True)
        body, fraction = np.array(ids, dtype=int), np.array(fractions, dtype=float)
        noise = scanner.rng.normal(0.0, SCAN_NOISE, beams)
        ranges = np.minimum(reach, inner + fraction * (reach - inner) + noise).round(4)
        scan: list[float] = np.where(body < 0, reach, ranges).tolist()
        return scan

    # called by World
    def _true_pose(self) -> Pose:
        pos, orn = p.getBasePositionAndOrientation(self._chassis.body, physicsClientId=self._cid)
        return (pos[0], pos[1], yaw_of(orn))

    def _unwind(self) -> None:
        """Drop the lead a blocked walk built up, so a new command starts from where we are."""
        ax, ay, ayaw = self._true_pose()
        x, y, yaw = self._target
        if math.hypot(x - ax, y - ay) > UNWIND_XY or abs(wrap(yaw - ayaw)) > UNWIND_YAW:
            self._target = (ax, ay, ayaw)
            self._push_target()

    def _push_target(self) -> None:
        x, y, yaw = self._target
        orn = (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
        p.changeConstraint(self._chassis.mocap, jointChildPivot=[x, y, self._chassis.hover],
                           jointChildFrameOrientation=orn, maxForce=self._chassis.max_force,
                           physicsClientId=self._cid)

    def _before_advance(self, dt: float) -> None:
        """Called once at the start of each `World.advance` (the humanoid keeps its leash every step)."""

    def _pre_step(self, dt: float) -> None:
        """`_ahead`, `_leashed` and `_push_target` in one, the same arithmetic: called for every
        walking body after every physics step."""
        forward, sideways, turn = self._cmd
        if forward == 0.0 and sideways == 0.0 and turn == 0.0:
            return
        x, y, yaw = self._target
        c, s = math.cos(yaw), math.sin(yaw)
        x, y = x + (c * forward - s * sideways) * dt, y + (s * forward + c * sideways) * dt
        yaw += turn * dt
        chassis, cid = self._chassis, self._cid
        pos, orn = p.getBasePositionAndOrientation(chassis.body, physicsClientId=cid)
        ax, ay, ayaw = pos[0], pos[1], yaw_of(orn)
        dx, dy = x - ax, y - ay
        dist = math.hypot(dx, dy)
        leash = max(LEASH_XY, 8.0 * math.hypot(forward, sideways) * dt)
        if dist > leash:
            x, y = ax + dx * leash / dist, ay + dy * leash / dist
        yaw = ayaw + clamp(wrap(yaw - ayaw), -LEASH_YAW, LEASH_YAW)
        self._target = (x, y, yaw)
        orn = (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
        p.changeConstraint(chassis.mocap, jointChildPivot=[x, y, chassis.hover],
                           jointChildFrameOrientation=orn, maxForce=chassis.max_force, physicsClientId=cid)

    def _ahead(self, dt: float) -> Pose:
        """The target moved on by the commanded velocity for `dt`."""
        forward, sideways, turn = self._cmd
        x, y, yaw = self._target
        c, s = math.cos(yaw), math.sin(yaw)
        return x + (c * forward - s * sideways) * dt, y + (s * forward + c * sideways) * dt, yaw + turn * dt

    def _leashed(self, target: Pose, dt: float) -> Pose:
        """The target kept near the true pose, so a blocked body does not build up a lead."""
        forward, sideways, _ = self._cmd
        x, y, yaw = target
        ax, ay, ayaw = self._true_pose()
        dx, dy = x - ax, y - ay
        dist = math.hypot(dx, dy)
        leash = max(LEASH_XY, 8.0 * math.hypot(forward, sideways) * dt)  # the constraint lags ~5 steps
        if dist > leash:
            x, y = ax + dx * leash / dist, ay + dy * leash / dist
        return x, y, ayaw + clamp(wrap(yaw - ayaw), -LEASH_YAW, LEASH_YAW)

    def _after_advance(self, bumped: bool, seconds: float = 0.0, read: int = 0) -> None:
        pose = self._true_pose()
        self._odometry.update(pose)
        self._bumped = bumped
        if self._battery is not None:
            self._battery.drain(seconds, math.dist(pose[:2], self._last_xy),
                                math.dist(pose[:2], self._start_xy), read)
        self._last_xy = pose[:2]

    def _fail(self) -> None:
        """It stops where it stands and takes no more commands (the world lets go of its load)."""
        self.stop()
        self.failed = True
