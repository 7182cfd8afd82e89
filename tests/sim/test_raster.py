"""The rasteriser draws what pybullet's tiny renderer draws, to the odd edge pixel."""

from __future__ import annotations

import math
from collections.abc import Callable

import cv2
import numpy as np
import pybullet as p
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_sim.camera import TinyRenderer, world_camera
from hfsm_sim.raster import SKY, Rasteriser, _spans
from hfsm_sim.robot import Robot
from hfsm_sim.room import _static_box
from hfsm_sim.world import World

TWO = {"r1": {"x": -1.0, "y": -0.3, "yaw": 20.0}, "r2": {"x": 1.0, "y": 0.4, "yaw": 200.0}}


def _both(robot: Robot, camera: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    pos, orn = p.getBasePositionAndOrientation(robot._body.body, physicsClientId=robot._cid)
    view = world_camera(robot.camera_model(camera), pos, orn)
    tiny, tiny_mask = TinyRenderer(robot._cid).render(view, segmentation=True)
    ours, mask = robot._render(camera, segmentation=True)
    assert tiny_mask is not None and mask is not None
    return tiny, ours, tiny_mask, mask


@pytest.mark.parametrize("size", [(160, 120), (640, 480)])
@pytest.mark.parametrize("camera", ["forward", "down"])
def test_same_picture_as_the_tiny_renderer(world_factory: Callable[..., World],
                                           size: tuple[int, int], camera: str) -> None:
    world = world_factory(TWO, image_size=size)
    for step in range(3):
        for name, robot in world.robots.items():
            robot.set_velocity(0.1, 0.0, 0.3 if name == "r1" else -0.2)
            robot.set_head(0.6 * math.sin(step), 0.25 * step)
            robot.arms_lift(0.2 + 0.1 * step)
        world.advance(1.5)
        for robot in world.robots.values():
            tiny, ours, tiny_mask, mask = _both(robot, camera)
            assert ours.shape == tiny.shape and ours.dtype == np.uint8
            same = (ours == tiny).all(axis=2)
            assert same.mean() > 0.995  # only pixels on an edge may differ
            assert (mask == tiny_mask).mean() > 0.995
            # the same light: every colour of more than an edge is one the tiny renderer drew
            colours, counts = np.unique(ours.reshape(-1, 3), axis=0, return_counts=True)
            theirs = {tuple(c) for c in tiny.reshape(-1, 3)}
            assert all(tuple(c) in theirs for c in colours[counts >= 10])


def test_sky_is_white_and_the_mask_marks_it(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -1.5, "y": 0.0, "yaw": 0.0}})
    robot = world.robots["r1"]
    robot.set_head(0.0, math.radians(-38))  # look up over the far wall
    world.advance(1.0)
    rgb, mask = world.truth.camera_with_mask(robot, "forward")
    sky = mask == -1
    assert sky.any()
    assert (rgb[sky] == SKY).all()


def test_a_body_added_later_is_drawn(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -1.5, "y": 0.0, "yaw": 0.0}})
    robot = world.robots["r1"]
    robot.image("forward")
    box = _static_box(world.client, (0.2, 0.2, 0.4), (-0.8, 0.0, 0.4), (1.0, 0.0, 0.0))
    _, mask = world.truth.camera_with_mask(robot, "forward")
    assert (mask == box).mean() > 0.05


def test_a_new_rasteriser_reads_the_scene_afresh(world_factory: Callable[..., World]) -> None:
    world = world_factory(TWO)
    robot = world.robots["r1"]
    pictures = [robot.image("down")]
    robot._cameras = Rasteriser(world.client)
    pictures.append(robot.image("down"))
    assert (pictures[0] == pictures[1]).all()


def test_faces_kept_for_a_physics_step_draw_what_a_fresh_placement_draws(
        world_factory: Callable[..., World]) -> None:
    """The world's rasteriser places the faces once a physics step; moving robots, several images a
    step and a body added mid-run give the pictures of a rasteriser that places them for every image."""
    world = world_factory(TWO)
    fresh = Rasteriser(world.client)
    for robot in world.robots.values():
        robot.set_velocity(0.1, 0.0, 0.4)
    for step in range(4):
        if step == 2:
            _static_box(world.client, (0.2, 0.2, 0.4), (0.0, 0.0, 0.4), (1.0, 0.0, 0.0))
        for robot in world.robots.values():
            for camera in ("forward", "down"):
                kept, kept_mask = robot._render(camera, segmentation=True)
                pos, orn = p.getBasePositionAndOrientation(robot._body.body, physicsClientId=robot._cid)
                drawn, mask = fresh.render(world_camera(robot.camera_model(camera), pos, orn),
                                           segmentation=True)
                assert (kept == drawn).all() and kept_mask is not None and mask is not None
                assert (kept_mask == mask).all()
        world.advance(0.25)
    assert world.robots["r1"]._cameras._placed is not None  # type: ignore[attr-defined]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-5, 25), st.floats(-5, 20)), min_size=3, max_size=3),
       st.booleans())
def test_spans_sample_pixels_as_points(corners: list[tuple[float, float]], clockwise: bool
                                       ) -> None:
    """A triangle covers pixel (i, j) iff point (i, j) lies in it (edges included)."""
    u = np.array([c[0] for c in corners] + [corners[-1][0]])
    v = np.array([c[1] for c in corners] + [corners[-1][1]])
    if clockwise:
        u, v = u[::-1].copy(), v[::-1].copy()
    (a, b, c) = corners
    area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
    if abs(area) < 1.0:
        return
    first, last, rows = _spans(u[None], v[None], 20, 15)
    for j in range(15):
        for i in range(20):
            signs = [(q[0] - o[0]) * (j - o[1]) - (q[1] - o[1]) * (i - o[0])
                     for o, q in ((a, b), (b, c), (c, a))]
            margin = min(abs(s) for s in signs)
            if margin < 1e-6:
                continue  # on an edge: either way is fine
            inside = all(s > 0 for s in signs) or all(s < 0 for s in signs)
            assert (rows[0, j] and first[0, j] <= i <= last[0, j]) == inside


def test_a_light_robot_s_cylinder_is_drawn_where_the_tiny_renderer_draws_it(
        world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -1.2, "y": 0.0, "yaw": 0.0},
                           "r2": {"x": 0.0, "y": 1.0, "yaw": 0.0, "body": "light"}},
                          table={"x": 1.2, "y": -1.2})
    robot = world.robots["r1"]
    robot.set_head(math.radians(40), 0.0)
    world.advance(1.0)
    tiny, ours, tiny_mask, mask = _both(robot, "forward")
    light = world.truth.robot_id("r2")
    assert (tiny_mask == light).mean() > 0.02
    assert ((mask == light) == (tiny_mask == light)).mean() > 0.995
    both = (mask == light) & (tiny_mask == light)
    # flat sides where the tiny renderer shades smoothly (its normals lean up towards the top):
    # the same hue, a little brighter or darker
    hue, hue_tiny = (cv2.cvtColor(im[None, both], cv2.COLOR_RGB2HSV)[0].astype(int)
                     for im in (ours, tiny))
    assert (np.abs(hue[:, 0] - hue_tiny[:, 0]) <= 2).mean() > 0.98
    assert np.abs(hue[:, 2] - hue_tiny[:, 2]).mean() < 12
