"""Floor, walls and the blue table as pybullet bodies."""

from __future__ import annotations

import math
from dataclasses import dataclass

import pybullet as p

from hfsm_sim.profile import FLOOR_COLOUR, TABLE_COLOUR, WALL_COLOUR
from hfsm_sim.scenario import Room, TableSpec

TOP_THICKNESS = 0.03
LEG_SIDE = 0.035
WALL_THICKNESS = 0.1


@dataclass(frozen=True)
class RoomBodies:
    floor: int
    walls: tuple[int, ...]


@dataclass(frozen=True)
class TableBody:
    """The table body; its base frame is at its centre of mass, `com_height` above the floor."""

    body: int
    spec: TableSpec
    com_height: float

    @property
    def underside(self) -> float:
        """Height of the underside of the top above the table's feet."""
        return self.spec.height - TOP_THICKNESS


def _static_box(cid: int, half: tuple[float, float, float], pos: tuple[float, float, float],
                colour: tuple[float, float, float]) -> int:
    col = p.createCollisionShape(p.GEOM_BOX, halfExtents=half, physicsClientId=cid)
    vis = p.createVisualShape(p.GEOM_BOX, halfExtents=half, rgbaColor=[*colour, 1.0],
                              specularColor=[0, 0, 0], physicsClientId=cid)
    return int(p.createMultiBody(0.0, col, vis, basePosition=pos, physicsClientId=cid))


def build_room(cid: int, room: Room) -> RoomBodies:
    """Floor top at z=0; walls' inner faces at x=+-width/2 and y=+-depth/2."""
    hw, hd, h, t = room.width / 2, room.depth / 2, room.wall_height, WALL_THICKNESS
    floor = _static_box(cid, (hw + t, hd + t, 0.05), (0.0, 0.0, -0.05), FLOOR_COLOUR)
    walls = (
        _static_box(cid, (t / 2, hd + t, h / 2), (hw + t / 2, 0.0, h / 2), WALL_COLOUR),
        _static_box(cid, (t / 2, hd + t, h / 2), (-hw - t / 2, 0.0, h / 2), WALL_COLOUR),
        _static_box(cid, (hw, t / 2, h / 2), (0.0, hd + t / 2, h / 2), WALL_COLOUR),
        _static_box(cid, (hw, t / 2, h / 2), (0.0, -hd - t / 2, h / 2), WALL_COLOUR),
    )
    return RoomBodies(floor=floor, walls=walls)


def _table_parts(spec: TableSpec) -> list[tuple[tuple[float, float, float], tuple[float, ...]]]:
    """(half extents, centre above the feet) of the top and the four legs."""
    top = ((spec.length / 2, spec.width / 2, TOP_THICKNESS / 2),
           (0.0, 0.0, spec.height - TOP_THICKNESS / 2))
    leg_h = (spec.height - TOP_THICKNESS) / 2
    lx, ly = spec.length / 2 - LEG_SIDE / 2, spec.width / 2 - LEG_SIDE / 2
    legs = [((LEG_SIDE / 2, LEG_SIDE / 2, leg_h), (sx * lx, sy * ly, leg_h))
            for sx in (1, -1) for sy in (1, -1)]
    return [top, *legs]


def build_table(cid: int, spec: TableSpec) -> TableBody:
    parts = _table_parts(spec)
    volumes = [8 * h[0] * h[1] * h[2] for h, _ in parts]
    com_z = sum(v * c[2] for v, (_, c) in zip(volumes, parts, strict=True)) / sum(volumes)
    halves = [list(h) for h, _ in parts]
    centres = [[c[0], c[1], c[2] - com_z] for _, c in parts]
    col = p.createCollisionShapeArray([p.GEOM_BOX] * len(parts), halfExtents=halves,
                                      collisionFramePositions=centres, physicsClientId=cid)
    vis = p.createVisualShapeArray([p.GEOM_BOX] * len(parts), halfExtents=halves,
                                   visualFramePositions=centres,
                                   rgbaColors=[[*TABLE_COLOUR, 1.0]] * len(parts),
                                   physicsClientId=cid)
    orn = p.getQuaternionFromEuler([0.0, 0.0, math.radians(spec.yaw)])
    body = p.createMultiBody(spec.mass, col, vis, basePosition=(spec.x, spec.y, com_z),
                             baseOrientation=orn, physicsClientId=cid)
    p.changeDynamics(body, -1, lateralFriction=0.5,
                     activationState=p.ACTIVATION_STATE_ENABLE_SLEEPING, physicsClientId=cid)
    return TableBody(body=int(body), spec=spec, com_height=com_z)
