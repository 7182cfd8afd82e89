from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest

from hfsm_sim.world import World

FACING_TABLE = {"r1": {"x": -1.0, "y": 0.0, "yaw": 0.0}}


def _blue(rgb: np.ndarray) -> np.ndarray:
    r, g, b = (rgb[..., i].astype(int) for i in range(3))
    return (b > 120) & (b > r + 60) & (b > g + 60)


@pytest.mark.parametrize("size", [(160, 120), (640, 480), (80, 60)])
def test_image_shape_and_type(world_factory: Callable[..., World], size: tuple[int, int]) -> None:
    world = world_factory(FACING_TABLE, image_size=size)
    for camera in ("forward", "down"):
        image = world.robots["r1"].image(camera)
        assert image.shape == (size[1], size[0], 3)
        assert image.dtype == np.uint8


@pytest.mark.parametrize("size", [(160, 120), (640, 480)])
def test_table_is_blue_where_truth_projects_it(world_factory: Callable[..., World],
                                               size: tuple[int, int]) -> None:
    world = world_factory(FACING_TABLE, image_size=size)
    robot = world.robots["r1"]
    rgb, mask = world.truth.camera_with_mask(robot, "forward")
    table = mask == world.truth.table_id
    assert table.sum() > 0.01 * table.size
    assert _blue(rgb)[table].mean() > 0.95
    assert _blue(rgb)[~table].mean() < 0.01
    model = robot.camera_model("forward")
    centre = world.truth.to_body_frame("r1", world.truth.table_corners().mean(axis=0))
    projected = model.project(centre)
    assert projected is not None
    u, v = int(projected[0]), int(projected[1])
    assert table[v, u]


def test_down_camera_ground_point_matches_truth(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -0.9, "y": 0.0, "yaw": 0.0}}, image_size=(160, 120))
    robot = world.robots["r1"]
    _, mask = world.truth.camera_with_mask(robot, "down")
    model = robot.camera_model("down")
    rows = np.nonzero((mask == world.truth.table_id).any(axis=1))[0]
    bottom = rows.max() + 1.0
    x, _ = model.ground_point(model.cx, bottom) or (math.nan, 0.0)
    near_feet_x = world.truth.to_body_frame("r1", (-0.4, 0.0, 0.0))[0]
    assert x == pytest.approx(near_feet_x, abs=0.03)


def test_head_turn_moves_the_view(world_factory: Callable[..., World]) -> None:
    world = world_factory(FACING_TABLE)
    robot = world.robots["r1"]
    robot.set_head(math.radians(30), 0.0)
    assert not robot.head_settled()
    world.advance(1.0)
    assert robot.head_settled()
    assert robot.head()[0] == pytest.approx(math.radians(30), abs=0.01)
    _, mask = world.truth.camera_with_mask(robot, "forward")
    table_cols = np.nonzero((mask == world.truth.table_id).any(axis=0))[0]
    assert table_cols.size and table_cols.min() > robot.camera_model().cx


def test_camera_model_matches_nao_profile(world_factory: Callable[..., World]) -> None:
    world = world_factory(FACING_TABLE, image_size=(160, 120))
    forward = world.robots["r1"].camera_model("forward")
    down = world.robots["r1"].camera_model("down")
    assert forward.hfov_deg == pytest.approx(60.9, abs=0.3)
    assert forward.vfov_deg == pytest.approx(47.6)
    assert math.degrees(down.pitch - forward.pitch) == pytest.approx(39.7)
    assert 0.45 < down.position[2] < forward.position[2] < 0.56


def test_images_are_deterministic(world_factory: Callable[..., World]) -> None:
    images = []
    for _ in range(2):
        world = world_factory({"r1": {"x": -1.0, "y": 0.3, "yaw": 10.0},
                               "r2": {"x": 1.0, "y": 0.0, "yaw": 180.0}}, seed=3)
        world.robots["r1"].set_velocity(0.1, 0.02, 0.2)
        world.advance(1.0)
        images.append(world.robots["r1"].image("forward"))
    assert np.array_equal(images[0], images[1])
