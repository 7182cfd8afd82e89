"""Localisation against the known room: a light robot's odometry corrected by its laser scans.

The room is a rectangle the team is told (`in.room`: width along x, depth along y, centred on 0).
Every scan, the beams' end points are placed by the pose estimate; those lying near one of the four
walls are matched to it (the rest hit robots or tables and are ignored), and the pose that puts
them on their walls is found by a few Gauss-Newton steps on (x, y, yaw), damped so that a direction
the walls seen do not fix (along the only wall in sight) keeps its odometry. The correction is kept
as a rigid transform applied to odometry, so the estimate moves with odometry between scans.
Nothing here reads the simulator's truth: only odometry, the scan and the room's size.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from hfsm_behaviours.approach.frames import wrap

Pose = tuple[float, float, float]
BEAMS, REACH = 60, 20.0  # a full turn every 6 degrees, 20 m (a Hokuyo UTM-30LX reaches 30 m)
SCAN_EVERY = 0.5  # seconds between scans
FRAMED_EVERY = 1.0  # seconds between a humanoid's scans for its frame (it walks 0.1 m/s)
GATES = (0.1, 0.05, 0.03)  # metres per metre of range, per Gauss-Newton step: a yaw error moves far
GATE_FLOOR, GATE_CAP = 0.1, 0.8  # points more; plus this, at most that
MIN_POINTS = 6  # beams on walls needed to correct at all
DAMPING = 2.0  # the prior's weight, in beams' worth: what holds an unseen direction
MAX_STEP, MAX_TURN = 0.5, 0.15  # metres and radians a scan may move the estimate at most


def _matches(pose: Pose, angles: np.ndarray, ranges: np.ndarray, half: tuple[float, float],
             gate: float) -> tuple[np.ndarray, np.ndarray]:
    """Residuals (metres off the wall) and their Jacobian rows for d(x, y, yaw), of the beams whose
    end points lie within `gate` (scaled by range) of a wall."""
    x, y, yaw = pose
    heading = yaw + angles
    px, py = x + ranges * np.cos(heading), y + ranges * np.sin(heading)
    off = np.stack([px - half[0], px + half[0], py - half[1], py + half[1]])
    wall = np.argmin(np.abs(off), axis=0)
    res = off[wall, np.arange(len(ranges))]
    keep = np.abs(res) < np.minimum(GATE_FLOOR + gate * ranges, GATE_CAP)
    along_x = wall < 2
    rows = np.where(along_x[:, None],
                    np.stack([np.ones_like(px), np.zeros_like(px), py - y], axis=1) * [1, 1, -1],
                    np.stack([np.zeros_like(px), np.ones_like(px), px - x], axis=1))
    return res[keep], rows[keep]


def correct(pose: Pose, scan: list[float], room: tuple[float, float], reach: float = REACH) -> Pose:
    """The pose that best puts the scan's wall points on the walls of a `room` (width, depth)
    centred on 0, starting from `pose`; `pose` itself when too few beams see a wall."""
    if not scan:
        return pose
    ranges = np.asarray(scan, dtype=float)
    angles = np.arange(len(ranges)) * (2 * math.pi / len(ranges))
    hit = ranges < reach * 0.999
    ranges, angles = ranges[hit], angles[hit]
    half = (room[0] / 2, room[1] / 2)
    est = np.asarray(pose, dtype=float)
    for gate in GATES:
        res, rows = _matches((est[0], est[1], est[2]), angles, ranges, half, gate)
        if len(res) < MIN_POINTS:
            return pose if gate == GATES[0] else _bounded(pose, est)
        normal = rows.T @ rows + DAMPING * np.eye(3)
        est = est - np.linalg.solve(normal, rows.T @ res)
    return _bounded(pose, est)


def _bounded(pose: Pose, est: np.ndarray) -> Pose:
    dx, dy = est[0] - pose[0], est[1] - pose[1]
    step = math.hypot(dx, dy)
    if step > MAX_STEP:
        dx, dy = dx / step * MAX_STEP, dy / step * MAX_STEP
    turn = max(-MAX_TURN, min(MAX_TURN, wrap(float(est[2]) - pose[2])))
    return (pose[0] + dx, pose[1] + dy, wrap(pose[2] + turn))


@dataclass
class Fix:
    """A rigid transform (turn `yaw` about the origin, then shift by (x, y)) taking odometry to the
    corrected estimate."""

    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0

    def apply(self, odom: Pose) -> Pose:
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        x, y = self.x + c * odom[0] - s * odom[1], self.y + s * odom[0] + c * odom[1]
        return (x, y, wrap(odom[2] + self.yaw))

    @staticmethod
    def between(odom: Pose, estimate: Pose) -> Fix:
        yaw = wrap(estimate[2] - odom[2])
        c, s = math.cos(yaw), math.sin(yaw)
        return Fix(estimate[0] - (c * odom[0] - s * odom[1]), estimate[1] - (s * odom[0] + c * odom[1]), yaw)


class Localised:
    """A light robot as the behaviours drive it: everything is the body's, except `odometry()`,
    which is its odometry corrected against the room by its laser (`update`, every SCAN_EVERY s)."""

    body_kind = "light"

    def __init__(self, robot: Any, room: tuple[float, float]) -> None:
        self.body = robot
        self.room = room
        self.fix = Fix()

    def __getattr__(self, name: str) -> Any:
        return getattr(self.body, name)

    def odometry(self) -> Pose:
        return self.fix.apply(self.body.odometry())

    def update(self) -> None:
        odom = self.body.odometry()
        scan = self.body.scan(BEAMS, REACH)
        self.fix = Fix.between(odom, correct(self.fix.apply(odom), scan, self.room))


def compose(a: Pose, b: Pose) -> Pose:
    """Pose `b`, given in the frame of pose `a`, in `a`'s own frame."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], wrap(a[2] + b[2]))


def relative(a: Pose, b: Pose) -> Pose:
    """Pose `b` in the frame of pose `a` (the inverse of `compose`)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2]))


class Framed:
    """A humanoid as the behaviours drive it: everything is the body's until its machine tells it
    where it started in a room (`localise`: the start pose it was told, the room's size); from then
    on `odometry()` (still in its own start frame) and the cameras' poses are its odometry corrected
    against the room's walls by its range finder (`update`): the error of the told start (its yaw
    moves far points most) and the drift of long walks. Never told, it is its body exactly."""

    def __init__(self, robot: Any) -> None:
        self.body = robot
        self.fix: Fix | None = None
        self.origin: Pose = (0.0, 0.0, 0.0)
        self.room: tuple[float, float] = (0.0, 0.0)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.body, name)

    def localise(self, origin: Pose, room: tuple[float, float]) -> None:
        self.origin, self.room = origin, room
        if self.fix is None:
            self.fix = Fix()
            self.update()

    def odometry(self) -> Pose:
        odom: Pose = self.body.odometry()
        return odom if self.fix is None else self.fix.apply(odom)

    def camera_model(self, camera: str = "forward") -> Any:
        model = self.body.camera_model(camera)
        return model if self.fix is None else replace(model, odom=self.odometry())

    def update(self) -> None:
        if self.fix is None or self.body.failed:
            return
        odom = self.body.odometry()
        scan = self.body.scan(BEAMS, REACH)
        room = correct(compose(self.origin, self.fix.apply(odom)), scan, self.room)
        self.fix = Fix.between(odom, relative(self.origin, room))
