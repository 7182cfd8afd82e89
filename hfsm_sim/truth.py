"""Ground truth of a World. Only the scorer, the recorder and tests may use it."""

from __future__ import annotations

import math

import numpy as np
import pybullet as p

from hfsm_sim.body import RobotBody, yaw_of
from hfsm_sim.robot import Robot
from hfsm_sim.room import RoomBodies, TableBody
from hfsm_sim.scenario import Room


class Truth:
    """Robots by name (`robot_bodies`: the humanoids' bodies; `robot_ids`: every robot's pybullet
    body), tables by index in scenario order (the first by default)."""

    def __init__(self, cid: int, room: Room, bodies: RoomBodies, tables: list[TableBody],
                 robots: dict[str, RobotBody], robot_ids: dict[str, int]) -> None:
        self._cid = cid
        self.room = room
        self.room_bodies = bodies
        self.tables = tables
        self.robot_bodies = robots
        self.robot_ids = robot_ids

    @property
    def table(self) -> TableBody:
        if not self.tables:
            raise LookupError("this room has no table")
        return self.tables[0]

    @property
    def table_id(self) -> int:
        return self.table.body

    def robot_id(self, name: str) -> int:
        return self.robot_ids[name]

    def robot_pose(self, name: str) -> tuple[float, float, float]:
        """World (x, y, yaw) of a robot's base."""
        pos, orn = p.getBasePositionAndOrientation(self.robot_id(name), physicsClientId=self._cid)
        return (pos[0], pos[1], yaw_of(orn))

    def robot_tilt(self, name: str) -> float:
        """Angle (rad) between a robot's up axis and the vertical."""
        _, orn = p.getBasePositionAndOrientation(self.robot_id(name), physicsClientId=self._cid)
        return _tilt(orn)

    def to_body_frame(self, name: str, point: tuple[float, float, float] | np.ndarray
                      ) -> tuple[float, float, float]:
        """A world point in a robot's body frame (x forward, y left, z up from the floor)."""
        x, y, yaw = self.robot_pose(name)
        dx, dy = float(point[0]) - x, float(point[1]) - y
        c, s = math.cos(yaw), math.sin(yaw)
        return (c * dx + s * dy, -s * dx + c * dy, float(point[2]))

    def camera_with_mask(self, robot: Robot, camera: str) -> tuple[np.ndarray, np.ndarray]:
        """RGB and the body-id segmentation mask of a robot's camera (tests only)."""
        rgb, mask = robot._render(camera, segmentation=True)
        assert mask is not None
        return rgb, mask

    def table_pose(self, index: int = 0) -> tuple[float, float, float, float]:
        """(x, y, lift, yaw): the table's centre, its lift above resting height, its yaw."""
        table = self.tables[index]
        pos, orn = p.getBasePositionAndOrientation(table.body, physicsClientId=self._cid)
        return (pos[0], pos[1], pos[2] - table.com_height, yaw_of(orn))

    def table_tilt(self, index: int = 0) -> float:
        """Angle (rad) between the table top's normal and the vertical."""
        _, orn = p.getBasePositionAndOrientation(self.tables[index].body, physicsClientId=self._cid)
        return _tilt(orn)

    def table_matrix(self, index: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """World position of the table's centre of mass and its rotation matrix."""
        pos, orn = p.getBasePositionAndOrientation(self.tables[index].body, physicsClientId=self._cid)
        return np.asarray(pos), np.array(p.getMatrixFromQuaternion(orn)).reshape(3, 3)

    def table_corners(self, z: float | None = None, index: int = 0) -> np.ndarray:
        """4 x 3 world corners of the table top (at height z above the feet, default top)."""
        table = self.tables[index]
        spec = table.spec
        pos, rot = self.table_matrix(index)
        height = spec.height if z is None else z
        local = np.array([[sx * spec.length / 2, sy * spec.width / 2,
                           height - table.com_height]
                          for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))])
        return np.asarray(local @ rot.T + pos)

    def table_wall_distance(self, index: int = 0) -> float:
        """Smallest gap between the table top's footprint and a wall's inner face."""
        hw, hd = self.room.width / 2, self.room.depth / 2
        corners = self.table_corners(index=index)
        return float(max(0.0, min(np.min(hw - np.abs(corners[:, 0])),
                                  np.min(hd - np.abs(corners[:, 1])))))


def _tilt(orn: tuple[float, ...]) -> float:
    qx, qy = orn[0], orn[1]
    return math.acos(max(-1.0, min(1.0, 1.0 - 2.0 * (qx * qx + qy * qy))))
