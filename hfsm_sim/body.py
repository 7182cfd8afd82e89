"""The robot's pybullet body: a base (legs + torso) dragged by a mocap constraint, a head on
yaw and pitch joints and a pair of arms on a vertical slide. Only the base collides."""

from __future__ import annotations

import math
from dataclasses import dataclass

import pybullet as p

from hfsm_sim.profile import BodyGeometry, MotionProfile

NECK, HEAD, ARMS = 0, 1, 2
JOINT_FORCE = {NECK: 20.0, HEAD: 20.0, ARMS: 300.0}
Colour = tuple[float, float, float]


@dataclass(frozen=True)
class RobotBody:
    body: int
    mocap: int
    geometry: BodyGeometry


def _rgba(colour: Colour, shade: float = 1.0) -> list[float]:
    return [c * shade for c in colour] + [1.0]


def _base_shapes(cid: int, g: BodyGeometry, colour: Colour) -> tuple[int, int]:
    col = p.createCollisionShape(p.GEOM_BOX, halfExtents=[g.half_depth, g.half_width,
                                 g.neck_height / 2], collisionFramePosition=[0, 0,
                                 g.neck_height / 2], physicsClientId=cid)
    leg_h = g.neck_height * 0.52
    torso_h = g.neck_height - leg_h
    vis = p.createVisualShapeArray(
        [p.GEOM_BOX] * 3,
        halfExtents=[[g.half_depth - 0.01, g.half_width - 0.01, torso_h / 2],
                     [0.045, 0.045, leg_h / 2], [0.045, 0.045, leg_h / 2]],
        visualFramePositions=[[0, 0, leg_h + torso_h / 2], [0, 0.06, leg_h / 2],
                              [0, -0.06, leg_h / 2]],
        rgbaColors=[_rgba(colour), _rgba(colour, 0.7), _rgba(colour, 0.7)],
        physicsClientId=cid)
    return int(col), int(vis)


def _head_visual(cid: int, g: BodyGeometry, colour: Colour) -> int:
    s = g.head_size / 2
    return int(p.createVisualShapeArray(
        [p.GEOM_BOX, p.GEOM_BOX], halfExtents=[[s, s, s], [0.005, s * 0.75, s * 0.3]],
        visualFramePositions=[[0, 0, s], [s, 0, s * 1.1]],
        rgbaColors=[_rgba(colour), [0.1, 0.1, 0.1, 1.0]],
        physicsClientId=cid))


def _arms_visual(cid: int, g: BodyGeometry, colour: Colour) -> int:
    t = g.arm_thickness / 2
    half = [(g.hand_x + 0.02) / 2, t, t]
    return int(p.createVisualShapeArray(
        [p.GEOM_BOX] * 2, halfExtents=[half, half],
        visualFramePositions=[[half[0] - 0.01, sy * g.hand_y, -t] for sy in (1, -1)],
        rgbaColors=[_rgba(colour, 0.85)] * 2,
        physicsClientId=cid))


def build_robot(cid: int, g: BodyGeometry, m: MotionProfile, colour: Colour,
                pose: tuple[float, float, float]) -> RobotBody:
    col, vis = _base_shapes(cid, g, colour)
    dummy = p.createCollisionShape(p.GEOM_SPHERE, radius=0.02, physicsClientId=cid)
    x, y, yaw = pose
    orn = p.getQuaternionFromEuler([0.0, 0.0, yaw])
    body = int(p.createMultiBody(
        g.mass - 1.0, col, vis, basePosition=[x, y, g.hover], baseOrientation=orn,
        linkMasses=[0.1, 0.5, 0.4], linkCollisionShapeIndices=[dummy] * 3,
        linkVisualShapeIndices=[-1, _head_visual(cid, g, colour), _arms_visual(cid, g, colour)],
        linkPositions=[[0, 0, g.neck_height], [0, 0, 0], [0, 0, 0]],
        linkOrientations=[[0, 0, 0, 1]] * 3, linkInertialFramePositions=[[0, 0, 0]] * 3,
        linkInertialFrameOrientations=[[0, 0, 0, 1]] * 3, linkParentIndices=[0, 1, 0],
        linkJointTypes=[p.JOINT_REVOLUTE, p.JOINT_REVOLUTE, p.JOINT_PRISMATIC],
        linkJointAxis=[[0, 0, 1], [0, 1, 0], [0, 0, 1]], physicsClientId=cid))
    for link in (NECK, HEAD, ARMS):
        p.setCollisionFilterGroupMask(body, link, 0, 0, physicsClientId=cid)
    p.resetJointState(body, ARMS, m.arm_low - g.hover, physicsClientId=cid)
    speeds = {NECK: m.head_speed, HEAD: m.head_speed, ARMS: m.arm_speed}
    targets = {NECK: 0.0, HEAD: 0.0, ARMS: m.arm_low - g.hover}
    for joint in (NECK, HEAD, ARMS):
        drive_joint(cid, body, joint, targets[joint], speeds[joint])
    mocap = p.createConstraint(body, -1, -1, -1, p.JOINT_FIXED, [0, 0, 0], [0, 0, 0],
                               [x, y, g.hover], childFrameOrientation=orn, physicsClientId=cid)
    p.changeConstraint(mocap, maxForce=g.base_max_force, physicsClientId=cid)
    return RobotBody(body=body, mocap=int(mocap), geometry=g)


def drive_joint(cid: int, body: int, joint: int, target: float, speed: float) -> None:
    p.setJointMotorControl2(body, joint, p.POSITION_CONTROL, targetPosition=target,
                            force=JOINT_FORCE[joint], maxVelocity=speed, physicsClientId=cid)


def yaw_of(orn: tuple[float, ...]) -> float:
    qx, qy, qz, qw = orn
    return math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
