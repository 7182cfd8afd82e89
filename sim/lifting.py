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

from sim.body import ARMS, RobotBody
from sim.room import TableBody

SLIP_DEG = 20.0
REACH = 0.12
STRETCH = 0.05
GRIP_TOLERANCE = 0.003
FLOOR_TOLERANCE = 0.004
LOAD_TAU = 0.05


class Arms(Protocol):
    def _arms_active(self) -> bool: ...
    def _arms_lowering(self) -> bool: ...


@dataclass
class _Hands:
    body: RobotBody
    grips: list[tuple[int, np.ndarray, int]] = field(default_factory=list)
    previous: list[float] | None = None
    load: np.ndarray = field(default_factory=lambda: np.zeros(3))
    give: np.ndarray = field(default_factory=lambda: np.zeros((2, 3)))


class Lifting:
    def __init__(self, cid: int, table: TableBody, bodies: dict[str, RobotBody],
                 slip_deg: float = SLIP_DEG, dt: float = 1.0 / 120) -> None:
        self._cid = cid
        self._smoothing = min(1.0, dt / LOAD_TAU)
        self._table = table
        self._hands = {name: _Hands(body) for name, body in bodies.items()}
        self._arms: dict[str, Arms] = {}
        self.slip = math.radians(slip_deg)
        self.dropped = False

    def bind(self, arms: Mapping[str, Arms]) -> None:
        self._arms = dict(arms)

    def holding(self, name: str) -> bool:
        return bool(self._hands[name].grips)

    def load(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """What this robot's hands feel, world frame: the force (N) the grips put on them,
        summed and low-passed, and each hand's give (m; rows: left hand, right hand), how far
        its grip pulls it off the posture the arm holds. Zeros when they hold nothing."""
        hands = self._hands[name]
        return hands.load.copy(), hands.give.copy()

    def update(self) -> None:
        """Call after every physics step."""
        table: tuple[np.ndarray, np.ndarray] | None = None
        for name, hands in self._hands.items():
            if not hands.grips and not self._arms[name]._arms_active():
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

    def _measure_give(self, hands: _Hands, points: list[np.ndarray],
                      table: tuple[np.ndarray, np.ndarray]) -> None:
        hands.give = np.zeros((2, 3))
        for _, anchor, index in hands.grips:
            hands.give[index] = table[0] + table[1] @ anchor - points[index]

    def _feel(self) -> None:
        for hands in self._hands.values():
            force = np.zeros(3)
            for grip in hands.grips:
                force += p.getConstraintState(grip[0], physicsClientId=self._cid)[:3]
            if not hands.grips:
                hands.give = np.zeros((2, 3))
                hands.load = force
            else:
                hands.load = hands.load + self._smoothing * (force - hands.load)

    def _table_pose(self) -> tuple[np.ndarray, np.ndarray]:
        pos, orn = p.getBasePositionAndOrientation(self._table.body, physicsClientId=self._cid)
        return np.asarray(pos), np.array(p.getMatrixFromQuaternion(orn)).reshape(3, 3)

    def _hand_points(self, body: RobotBody) -> list[np.ndarray]:
        g = body.geometry
        state = p.getLinkState(body.body, ARMS, physicsClientId=self._cid)
        rot = np.array(p.getMatrixFromQuaternion(state[5])).reshape(3, 3)
        origin = np.asarray(state[4])
        return [origin + rot @ np.array([g.hand_x, sy * g.hand_y, 0.0]) for sy in (1, -1)]

    def _try_grip(self, hands: _Hands, points: list[np.ndarray],
                  table: tuple[np.ndarray, np.ndarray]) -> None:
        spec, com_h = self._table.spec, self._table.com_height
        locals_ = [table[1].T @ (pt - table[0]) for pt in points]
        heights = [float(loc[2] + com_h) for loc in locals_]
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

    def _grip(self, hands: _Hands, index: int, anchor: np.ndarray) -> None:
        g = hands.body.geometry
        p.changeDynamics(self._table.body, -1, activationState=p.ACTIVATION_STATE_WAKE_UP,
                         physicsClientId=self._cid)
        hand = [g.hand_x, (1 if index == 0 else -1) * g.hand_y, 0.0]
        cid = p.createConstraint(self._table.body, -1, hands.body.body, ARMS,
                                 p.JOINT_POINT2POINT, [0, 0, 0], anchor.tolist(), hand,
                                 physicsClientId=self._cid)
        p.changeConstraint(cid, maxForce=g.hand_max_force, physicsClientId=self._cid)
        hands.grips.append((int(cid), anchor, index))

    def _check_grips(self, name: str, hands: _Hands, points: list[np.ndarray],
                     table: tuple[np.ndarray, np.ndarray]) -> None:
        for grip in list(hands.grips):
            anchor_world = table[0] + table[1] @ grip[1]
            if np.linalg.norm(anchor_world - points[grip[2]]) > STRETCH:
                self.dropped = self.dropped or not self._landed(points, table)
                self._release(hands, grip)
        if hands.grips and self._arms[name]._arms_lowering() and self._landed(points, table):
            for grip in list(hands.grips):
                self._release(hands, grip)

    def _landed(self, points: list[np.ndarray], table: tuple[np.ndarray, np.ndarray]) -> bool:
        """True if the two table feet nearest these hands are on the floor."""
        spec, com_h = self._table.spec, self._table.com_height
        feet = [table[0] + table[1] @ np.array([sx * spec.length / 2, sy * spec.width / 2,
                                                -com_h]) for sx in (1, -1) for sy in (1, -1)]
        middle = (points[0] + points[1]) / 2
        feet.sort(key=lambda foot: float(np.hypot(*(foot - middle)[:2])))
        return bool(max(feet[0][2], feet[1][2]) < FLOOR_TOLERANCE)

    def _check_slip(self, rot: np.ndarray) -> None:
        if math.acos(max(-1.0, min(1.0, float(rot[2, 2])))) <= self.slip:
            return
        self.dropped = True
        for hands in self._hands.values():
            for grip in list(hands.grips):
                self._release(hands, grip)

    def _release(self, hands: _Hands, grip: tuple[int, np.ndarray, int]) -> None:
        p.removeConstraint(grip[0], physicsClientId=self._cid)
        hands.grips.remove(grip)
        hands.previous = None
