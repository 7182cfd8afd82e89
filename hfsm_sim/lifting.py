"""Hands under the table: grips form when a rising hand meets the underside of a long side;
each grip is a POINT2POINT constraint (force but no torque, like a palm). A table tilted past
the slip angle slides off every hand and is recorded as dropped; so is a lifted table that
a hand loses because the robots walked apart (the hand pulled more than STRETCH away).

What the hands feel, `load(name)`: the force the grips apply to one robot's hands (world frame,
N, summed over its grips, low-passed with a LOAD_TAU time constant as arm joint currents are)
and each hand's give, how far its grip point has pulled it off the arm's posture (m)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
import pybullet as p

from hfsm_sim.body import ARMS, RobotBody
from hfsm_sim.room import TableBody

SLIP_DEG = 20.0
REACH = 0.12
STRETCH = 0.05
GRIP_TOLERANCE = 0.003
FLOOR_TOLERANCE = 0.004
LOAD_TAU = 0.05


Vec = tuple[float, float, float]
Mat = tuple[float, float, float, float, float, float, float, float, float]  # row-major 3x3
ZERO: Vec = (0.0, 0.0, 0.0)


def _apply(origin: Vec, m: Mat, v: Vec) -> Vec:
    """origin + m @ v, on tuples: numpy costs more than the arithmetic on 3-vectors at 120 Hz."""
    return (origin[0] + m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
            origin[1] + m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            origin[2] + m[6] * v[0] + m[7] * v[1] + m[8] * v[2])


def _local(origin: Vec, m: Mat, point: Vec) -> Vec:
    """m.T @ (point - origin): a world point in the frame (origin, m)."""
    x, y, z = point[0] - origin[0], point[1] - origin[1], point[2] - origin[2]
    return (m[0] * x + m[3] * y + m[6] * z, m[1] * x + m[4] * y + m[7] * z, m[2] * x + m[5] * y + m[8] * z)


def _sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


class Arms(Protocol):
    def _arms_active(self) -> bool: ...
    def _arms_lowering(self) -> bool: ...


Pose = tuple[Vec, Mat]
Grip = tuple[int, Vec, int]  # constraint id, anchor in the table's frame, hand index


@dataclass
class _Hands:
    body: RobotBody
    grips: list[Grip] = field(default_factory=list)
    previous: list[float] | None = None
    load: Vec = ZERO
    give: list[Vec] = field(default_factory=lambda: [ZERO, ZERO])


class Lifting:
    def __init__(self, cid: int, table: TableBody, bodies: dict[str, RobotBody],
                 slip_deg: float = SLIP_DEG, dt: float = 1.0 / 120,
                 hand_points: dict[int, list[Vec]] | None = None) -> None:
        """`hand_points`: a cache of the hands' points by robot body, shared by the liftings of
        one world, which empties it after every physics step; None: none."""
        self._cid = cid
        self._points = hand_points
        self._smoothing = min(1.0, dt / LOAD_TAU)
        self._table = table
        self._hands = {name: _Hands(body) for name, body in bodies.items()}
        self._arms: dict[str, Arms] = {}
        self.slip = math.radians(slip_deg)
        self.dropped = False
        self._limp: set[str] = set()  # robots that failed: their hands hold nothing, ever again
        self._grips = 0  # held by all hands
        self._rested = False  # the last update found no arm raised and nothing held

    def bind(self, arms: Mapping[str, Arms]) -> None:
        self._arms = dict(arms)

    def let_go(self, name: str) -> None:
        """A robot that failed: its hands release what they hold and never grip again."""
        self._limp.add(name)
        hands = self._hands[name]
        for grip in list(hands.grips):
            self._release(hands, grip)
        hands.give, hands.load = [ZERO, ZERO], ZERO

    def holding(self, name: str) -> bool:
        return bool(self._hands[name].grips)

    def load(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """What this robot's hands feel, world frame: the force (N) the grips put on them,
        summed and low-passed, and each hand's give (m; rows: left hand, right hand), how far
        its grip pulls it off the posture the arm holds. Zeros when they hold nothing."""
        hands = self._hands[name]
        return np.array(hands.load), np.array(hands.give)

    def update(self, arms_raised: bool = True) -> None:
        """Call after every physics step; `arms_raised` False when no robot's arms are above their
        lowest height: then, with nothing held, once this has reset every hand there is nothing to do."""
        if not arms_raised and not self._grips and self._rested:
            return
        self._rested = not arms_raised and not self._grips
        table: Pose | None = None
        for name, hands in self._hands.items():
            if not hands.grips and (name in self._limp or not self._arms[name]._arms_active()):
                hands.previous = None
                continue
            table = table or self._table_pose()
            points = self._hand_points(hands.body)
            if hands.grips:
                self._check_grips(name, hands, points, table)
                self._measure_give(hands, points, table)
            else:
                self._try_grip(hands, points, table)
        if table is not None and any(h.grips for h in self._hands.values()):
            self._check_slip(table[1])
        self._feel()

    def _measure_give(self, hands: _Hands, points: list[Vec], table: Pose) -> None:
        hands.give = [ZERO, ZERO]
        for _, anchor, index in hands.grips:
            hands.give[index] = _sub(_apply(table[0], table[1], anchor), points[index])

    def _feel(self) -> None:
        for hands in self._hands.values():
            if not hands.grips:
                hands.give = [ZERO, ZERO]
                hands.load = ZERO
                continue
            fx = fy = fz = 0.0
            for grip in hands.grips:
                f = p.getConstraintState(grip[0], physicsClientId=self._cid)
                fx, fy, fz = fx + f[0], fy + f[1], fz + f[2]
            k, (lx, ly, lz) = self._smoothing, hands.load
            hands.load = (lx + k * (fx - lx), ly + k * (fy - ly), lz + k * (fz - lz))

    def _table_pose(self) -> Pose:
        pos, orn = p.getBasePositionAndOrientation(self._table.body, physicsClientId=self._cid)
        return pos, p.getMatrixFromQuaternion(orn)

    def _hand_points(self, body: RobotBody) -> list[Vec]:
        cache = self._points
        if cache is None:
            return self._hands_now(body)
        points = cache.get(body.body)
        if points is None:
            points = cache[body.body] = self._hands_now(body)
        return points

    def _hands_now(self, body: RobotBody) -> list[Vec]:
        g = body.geometry
        state = p.getLinkState(body.body, ARMS, physicsClientId=self._cid)
        rot, origin = p.getMatrixFromQuaternion(state[5]), state[4]
        return [_apply(origin, rot, (g.hand_x, sy * g.hand_y, 0.0)) for sy in (1, -1)]

    def _try_grip(self, hands: _Hands, points: list[Vec], table: Pose) -> None:
        spec, com_h = self._table.spec, self._table.com_height
        locals_ = [_local(table[0], table[1], pt) for pt in points]
        heights = [loc[2] + com_h for loc in locals_]
        previous, hands.previous = hands.previous, heights
        if previous is None:
            return
        level = self._table.underside - GRIP_TOLERANCE
        for index, (loc, height, before) in enumerate(zip(locals_, heights, previous,
                                                          strict=True)):
            to_long, to_short = spec.width / 2 - abs(loc[1]), spec.length / 2 - abs(loc[0])
            under = 0.0 <= to_long <= REACH and to_long < to_short
            if under and before < level <= height:
                self._grip(hands, index, loc)

    def _grip(self, hands: _Hands, index: int, anchor: Vec) -> None:
        g = hands.body.geometry
        p.changeDynamics(self._table.body, -1, activationState=p.ACTIVATION_STATE_WAKE_UP,
                         physicsClientId=self._cid)
        hand = [g.hand_x, (1 if index == 0 else -1) * g.hand_y, 0.0]
        cid = p.createConstraint(self._table.body, -1, hands.body.body, ARMS,
                                 p.JOINT_POINT2POINT, [0, 0, 0], list(anchor), hand,
                                 physicsClientId=self._cid)
        p.changeConstraint(cid, maxForce=g.hand_max_force, physicsClientId=self._cid)
        hands.grips.append((int(cid), anchor, index))
        self._grips += 1

    def _check_grips(self, name: str, hands: _Hands, points: list[Vec], table: Pose) -> None:
        for grip in list(hands.grips):
            anchor_world = _apply(table[0], table[1], grip[1])
            if math.dist(anchor_world, points[grip[2]]) > STRETCH:
                self.dropped = self.dropped or not self._landed(points, table)
                self._release(hands, grip)
        if hands.grips and self._arms[name]._arms_lowering() and self._landed(points, table):
            for grip in list(hands.grips):
                self._release(hands, grip)

    def _landed(self, points: list[Vec], table: Pose) -> bool:
        """True if the two table feet nearest these hands are on the floor."""
        spec, com_h = self._table.spec, self._table.com_height
        feet = [_apply(table[0], table[1], (sx * spec.length / 2, sy * spec.width / 2, -com_h))
                for sx in (1, -1) for sy in (1, -1)]
        mx, my = (points[0][0] + points[1][0]) / 2, (points[0][1] + points[1][1]) / 2
        feet.sort(key=lambda foot: math.hypot(foot[0] - mx, foot[1] - my))
        return max(feet[0][2], feet[1][2]) < FLOOR_TOLERANCE

    def _check_slip(self, rot: Mat) -> None:
        if math.acos(max(-1.0, min(1.0, rot[8]))) <= self.slip:
            return
        self.dropped = True
        for hands in self._hands.values():
            for grip in list(hands.grips):
                self._release(hands, grip)

    def _release(self, hands: _Hands, grip: Grip) -> None:
        p.removeConstraint(grip[0], physicsClientId=self._cid)
        hands.grips.remove(grip)
        self._grips -= 1
        hands.previous = None
