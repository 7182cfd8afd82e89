from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_sim.perception import (
    DEFAULT_CONFIG,
    NO_BLOB,
    blob_from_mask,
    find_robot,
    find_robot_parts,
    find_robots,
    find_table,
    in_centre_band,
    is_below,
    is_near,
    table_distance,
)

SceneFactory = Callable[..., Any]
SIZES = [(160, 120), (640, 480)]
# a robot looking at the table's (-0.4, -0.25) corner from `dist` metres along the diagonal
DIAG = math.atan2(0.25, 0.4)


def corner_pose(dist: float, yaw_offset_deg: float = 0.0) -> dict[str, float]:
    x = -0.4 - dist * math.cos(math.radians(45))
    y = -0.25 - dist * math.sin(math.radians(45))
    return {"x": x, "y": y, "yaw": 45.0 + yaw_offset_deg}


@pytest.mark.parametrize("size", SIZES)
def test_table_blob_matches_segmentation(scene: SceneFactory, size: tuple[int, int]) -> None:
    s = scene({"r1": corner_pose(1.2, 10.0)}, size=size)
    blob = find_table(s.image())
    seg = s.table_seg()
    vs, us = np.nonzero(seg)
    assert blob.found
    assert blob.bbox == (us.min(), vs.min(), us.max(), vs.max())
    assert blob.area_px == pytest.approx(seg.sum(), rel=0.01)
    assert blob.centroid[0] == pytest.approx(us.mean() + 0.5, abs=0.5)
    assert blob.centroid[1] == pytest.approx(vs.mean() + 0.5, abs=0.5)
    assert blob.area_fraction == pytest.approx(seg.mean(), rel=0.01)


@pytest.mark.parametrize("size", SIZES)
def test_table_bbox_matches_projected_corners(scene: SceneFactory, size: tuple[int, int]) -> None:
    s = scene({"r1": corner_pose(1.5, -8.0)}, size=size)
    blob = find_table(s.image())
    pts = np.array([s.project(p) for p in s.table_points()])
    tol = 1.5 * size[0] / 160 ** 0 + 1.0  # a pixel or two at any size
    assert blob.left == pytest.approx(pts[:, 0].min(), abs=tol)
    assert blob.right + 1 == pytest.approx(pts[:, 0].max(), abs=tol)
    assert blob.top == pytest.approx(pts[:, 1].min(), abs=tol)
    assert blob.lowest_row + 1 == pytest.approx(pts[:, 1].max(), abs=tol)


@pytest.mark.parametrize(("dist", "pitch"), [(0.7, 29.0), (1.0, 20.0), (1.5, 0.0), (2.0, 0.0),
                                             (3.0, 0.0)])
@pytest.mark.parametrize("yaw", [0.0, 15.0])
def test_distance_and_bearing_to_nearest_foot(scene: SceneFactory, dist: float, pitch: float,
                                              yaw: float) -> None:
    """The forward camera sees the floor from ~1.2 m on with a level head: pitch it nearer."""
    s = scene({"r1": corner_pose(dist, yaw)})
    s.head(0.0, pitch)
    blob, ground = table_distance(s.image(), s.camera())
    fx, fy = s.nearest_foot()
    true_dist, true_bearing = math.hypot(fx, fy), math.atan2(fy, fx)
    assert ground.found and not ground.clipped
    assert ground.distance == pytest.approx(true_dist, rel=0.06)
    assert ground.bearing == pytest.approx(true_bearing, abs=math.radians(2.0))
    assert blob.found


def test_distance_agrees_across_resolutions(scene: SceneFactory) -> None:
    results = []
    for size in SIZES:
        s = scene({"r1": corner_pose(2.0, 5.0)}, size=size)
        results.append(table_distance(s.image(), s.camera())[1])
    assert results[0].distance == pytest.approx(results[1].distance, rel=0.04)
    assert results[0].bearing == pytest.approx(results[1].bearing, abs=math.radians(1.0))


def test_clipped_when_feet_out_of_view(scene: SceneFactory) -> None:
    s = scene({"r1": corner_pose(0.25)})
    blob, ground = table_distance(s.image(), s.camera())
    assert blob.touches_bottom and ground.clipped
    assert is_near(blob, s.camera().height)


def test_no_table_when_looking_away(scene: SceneFactory) -> None:
    s = scene({"r1": {**corner_pose(1.5), "yaw": 225.0}})
    blob, ground = table_distance(s.image(), s.camera())
    assert blob == NO_BLOB and not ground.found


@pytest.mark.parametrize("size", SIZES)
def test_other_robot_found_and_behind_table(scene: SceneFactory, size: tuple[int, int]) -> None:
    s = scene({"r1": {"x": -1.5, "y": 0.0, "yaw": 0.0}, "r2": {"x": 0.6, "y": 0.0, "yaw": 180.0}},
              size=size)
    image = s.image()
    r2 = find_robot(image, DEFAULT_CONFIG.robot_colours[1])
    seg = s.robot_seg("r2")
    vs, us = np.nonzero(seg)
    assert r2.found
    assert abs(r2.left - us.min()) <= 1 and abs(r2.right - us.max()) <= 1
    assert abs(r2.top - vs.min()) <= 1
    assert r2.centroid[0] == pytest.approx(us.mean() + 0.5, abs=0.02 * size[0])
    blobs = find_robots(image)
    assert not blobs[0].found and blobs[1] == r2
    assert is_below(find_table(image), r2)
    assert not is_below(r2, find_table(image))


def test_centre_band_is_the_papers_256_384() -> None:
    assert in_centre_band(256, 640) and in_centre_band(384, 640)
    assert not in_centre_band(255, 640) and not in_centre_band(385, 640)
    assert in_centre_band(64, 160) and not in_centre_band(63.9, 160)


@given(st.integers(0, 150), st.integers(0, 110), st.integers(4, 60), st.integers(4, 60))
def test_drawn_blue_rectangle_is_recovered_exactly(left: int, top: int, w: int, h: int) -> None:
    image = np.zeros((120, 160, 3), np.uint8)
    image[...] = (103, 78, 58)
    right, bottom = min(159, left + w - 1), min(119, top + h - 1)
    image[top:bottom + 1, left:right + 1] = (13, 51, 230)
    blob = find_table(image)
    assert blob.found
    assert blob.bbox == (left, top, right, bottom)
    assert blob.area_px == (right - left + 1) * (bottom - top + 1)
    assert blob.lowest_row == bottom
    assert blob.touches_bottom == (bottom == 119)


@given(st.integers(0, 2**32 - 1), st.sampled_from([(12, 16), (120, 160), (48, 64)]))
def test_no_crash_on_random_images(seed: int, shape: tuple[int, int]) -> None:
    image = np.random.default_rng(seed).integers(0, 256, (*shape, 3), dtype=np.uint8)
    blob = find_table(image)
    assert blob.found == (blob.area_px > 0)
    assert 0.0 <= blob.area_fraction <= 1.0
    assert blob_from_mask(np.zeros(shape, bool)) == NO_BLOB


@pytest.mark.parametrize("in_view", [["r2", "r3", "r4", "r5"], ["r6", "r7", "r8", "r9", "r10"]])
def test_ten_robot_colours_are_told_apart(scene: SceneFactory, in_view: list[str]) -> None:
    """Issue 10: rooms of several pairs need more than five colours; each of ten robots is found
    by its own colour alone, where it stands, and no colour of a robot out of view is found."""
    names = [f"r{i}" for i in range(2, 11)]
    robots = {"r1": {"x": -2.0, "y": 0.0, "yaw": 0.0}}
    for i, name in enumerate(names):
        if name in in_view:
            k = in_view.index(name)
            robots[name] = {"x": 1.5, "y": 1.6 - 0.8 * k, "yaw": 180.0}
        else:
            robots[name] = {"x": -2.7 - 0.4 * (i % 3), "y": 3.0 - 2.0 * (i // 3), "yaw": 0.0}
    s = scene(robots, size=(640, 480), table={"x": 3.0, "y": 3.0})
    image = s.image()
    blobs = find_robots(image)
    assert len(blobs) >= 10
    for i, name in enumerate(["r1", *names]):
        blob = blobs[i]
        if name not in in_view:
            assert not blob.found, f"{name}'s colour is out of view"
            continue
        vs, us = np.nonzero(s.robot_seg(name))
        assert blob.found
        assert abs(blob.left - us.min()) <= 1 and abs(blob.right - us.max()) <= 1
        assert abs(blob.top - vs.min()) <= 1


def test_robots_of_one_colour_are_told_apart(scene: SceneFactory) -> None:
    """Beyond ten robots colours repeat (r11 wears r1's): each robot of a colour in view is a
    blob of its own, where it stands, left to right; one robot is one blob (its limbs joined)."""
    robots = {"r1": {"x": -2.0, "y": 0.0, "yaw": 0.0}, "r2": {"x": 1.5, "y": 0.9, "yaw": 180.0}}
    for i in range(3, 12):
        robots[f"r{i}"] = {"x": -2.7 - 0.4 * (i % 3), "y": 3.0 - 0.6 * (i // 3), "yaw": 0.0}
    robots["r12"] = {"x": 1.5, "y": -0.9, "yaw": 180.0}  # the twelfth robot: r2's colour
    s = scene(robots, size=(640, 480), table={"x": 3.0, "y": 3.0})
    image = s.image()
    parts = find_robot_parts(image, DEFAULT_CONFIG.robot_colours[1])
    assert len(parts) == 2
    for blob, name in zip(parts, ["r2", "r12"], strict=True):
        vs, us = np.nonzero(s.robot_seg(name))
        assert abs(blob.left - us.min()) <= 1 and abs(blob.right - us.max()) <= 1
        assert abs(blob.lowest_row - vs.max()) <= 1
    assert len(find_robot_parts(image, DEFAULT_CONFIG.robot_colours[2])) == 0
