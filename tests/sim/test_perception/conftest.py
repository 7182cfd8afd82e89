"""Perception tests: a robot placed in a real sim World, and ground truth to compare with
(world.truth is used here only, never by hfsm_sim.perception)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from hfsm_sim.camera import CameraModel
from hfsm_sim.robot import Robot
from hfsm_sim.world import World


class Scene:
    """One robot's view of a world, with truth helpers."""

    def __init__(self, world: World, name: str = "r1") -> None:
        self.world, self.name = world, name
        self.robot: Robot = world.robots[name]

    def head(self, yaw_deg: float, pitch_deg: float) -> None:
        self.robot.set_head(math.radians(yaw_deg), math.radians(pitch_deg))
        for _ in range(40):
            if self.robot.head_settled():
                return
            self.world.advance(0.05)

    def camera(self, camera: str = "forward") -> CameraModel:
        return self.robot.camera_model(camera)

    def image(self, camera: str = "forward") -> np.ndarray:
        return self.robot.image(camera)

    def body(self, point: np.ndarray | tuple[float, float, float]) -> tuple[float, float, float]:
        return self.world.truth.to_body_frame(self.name, point)

    def project(self, point: np.ndarray | tuple[float, float, float],
                camera: str = "forward") -> tuple[float, float] | None:
        """Pixel of a world point in this robot's camera."""
        return self.camera(camera).project(self.body(point))

    def table_points(self) -> np.ndarray:
        """8 x 3 world points: the top's corners and the feet's outer corners."""
        truth = self.world.truth
        return np.vstack([truth.table_corners(), truth.table_corners(z=0.0)])

    def table_seg(self, camera: str = "forward") -> np.ndarray:
        _, mask = self.world.truth.camera_with_mask(self.robot, camera)
        return np.asarray(mask == self.world.truth.table_id)

    def robot_seg(self, other: str, camera: str = "forward") -> np.ndarray:
        _, mask = self.world.truth.camera_with_mask(self.robot, camera)
        return np.asarray(mask == self.world.truth.robot_id(other))

    def nearest_foot(self) -> tuple[float, float]:
        """Body-frame (x, y) of the table's floor corner nearest the forward camera."""
        cam = np.asarray(self.camera().position[:2])
        feet = [np.asarray(self.body(c)[:2]) for c in self.world.truth.table_corners(z=0.0)]
        best = min(feet, key=lambda f: float(np.linalg.norm(f - cam)))
        return (float(best[0]), float(best[1]))


SceneFactory = Callable[..., Scene]


@pytest.fixture
def scene(world_factory: Callable[..., World]) -> SceneFactory:
    """scene({"r1": {...}, ...}, size=(160, 120), room=..., table=...) -> Scene of r1."""

    def make(robots: dict[str, dict[str, float]], size: tuple[int, int] = (160, 120),
             **kwargs: Any) -> Scene:
        kwargs.setdefault("room", {"width": 8.0, "depth": 8.0})
        return Scene(world_factory(robots, image_size=size, **kwargs))

    return make
