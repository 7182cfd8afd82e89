"""The sim world's inputs computed from what one robot senses: its cameras, joints, odometry, battery.

Computed only when a machine reads them; one forward image a tick at most, shared by the inputs
that look at it. Nothing here reads the simulator's ground truth.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from hfsm_behaviours.drive.localise import Framed, Localised
from hfsm_sim import Robot
from hfsm_sim.light import LightRobot
from hfsm_sim.perception import Blob, blob_ground, find_robots, find_table, pixel_bearing, see_tables


def _degrees(radians: float) -> float:
    return round(math.degrees(float(radians)), 6)


SHOWN = ("pose", "tables_in_view")  # inputs whose last reading the trace carries (the monitor draws them)
LIGHT_BLIND = ("table_in_view", "table_bearing", "table_distance", "tables_in_view", "partner_in_view",
               "hand_give_left", "hand_give_right")


class Senses:
    """One robot's inputs at one tick (a new tick starts afresh)."""

    def __init__(self, robot: Robot | LightRobot | Localised | Framed, own_colour: int,
                 tasks: list[dict[str, Any]] | None = None, told: dict[str, Any] | None = None) -> None:
        self.own_colour = own_colour  # the index of its own body colour: it never sees itself
        self.tasks = tasks or []
        self._tick = -1
        self.last: dict[str, tuple[int, Any]] = {}  # input -> (tick, value) of its last reading, for SHOWN
        self._image: np.ndarray | None = None
        self._table: Blob | None = None
        self.readers: dict[str, Callable[[], Any]] = {
            "pose": lambda: self.pose(robot),
            "battery": robot.battery,
            "tasks": lambda: self.tasks,
            "start": lambda: (told or {}).get("start"),
            "room": lambda: (told or {}).get("room"),
        }
        if isinstance(robot, LightRobot | Localised):  # no cameras, no hands: what they would sense is null
            self.readers.update(dict.fromkeys(LIGHT_BLIND, lambda: None), holding=lambda: False)
            return
        self.robot = robot
        self.readers.update({
            "table_in_view": lambda: self.table().found,
            "table_bearing": self.table_bearing,
            "table_distance": self.table_distance,
            "tables_in_view": self.tables_in_view,
            "partner_in_view": self.partner_in_view,
            "hand_give_left": lambda: float(np.linalg.norm(robot.hand_load().left)),
            "hand_give_right": lambda: float(np.linalg.norm(robot.hand_load().right)),
            "holding": robot.holding,
        })

    def read(self, name: str, tick: int) -> Any:
        if tick != self._tick:
            self._tick, self._image, self._table = tick, None, None
        value = self.readers[name]()
        if name in SHOWN:
            self.last[name] = (tick, value)
        return value

    def image(self) -> np.ndarray:
        if self._image is None:
            self._image = self.robot.image("forward")
        return self._image

    def table(self) -> Blob:
        if self._table is None:
            self._table = find_table(self.image())
        return self._table

    def table_bearing(self) -> float | None:
        blob = self.table()
        if not blob.found:
            return None
        camera = self.robot.camera_model("forward")
        return _degrees(pixel_bearing(camera, blob.centroid[0], blob.centroid[1]))

    def table_distance(self) -> float | None:
        ground = blob_ground(self.table(), self.robot.camera_model("forward"))
        return round(ground.distance, 6) if ground.found else None

    def tables_in_view(self) -> list[dict[str, Any]]:
        seen = see_tables([(self.image(), self.robot.camera_model("forward"))])
        return [{"x": round(float(t.rect.x), 6), "y": round(float(t.rect.y), 6),
                 "heading": _degrees(t.rect.axis),
                 "length": round(float(t.rect.length), 6), "width": round(float(t.rect.width), 6),
                 "clipped": bool(t.clipped)} for t in seen]

    def partner_in_view(self) -> bool:
        blobs = find_robots(self.image())
        return any(b.found for i, b in enumerate(blobs) if i != self.own_colour)

    @staticmethod
    def pose(robot: Robot | LightRobot | Localised | Framed) -> dict[str, float]:
        x, y, yaw = robot.odometry()
        return {"x": round(float(x), 6), "y": round(float(y), 6), "yaw": _degrees(yaw)}
