from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import cv2
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sim.perception import DEFAULT_CONFIG, find_corner, in_centre_band
from sim.perception.corners import NO_CORNER, corner_from_mask, fit_line

SceneFactory = Callable[..., Any]
SIZES = [(160, 120), (640, 480)]


def corner_pose(dist: float, yaw_offset_deg: float = 0.0) -> dict[str, float]:
    """dist metres out along the diagonal from the table's (-0.4, -0.25) corner, facing it."""
    return {"x": -0.4 - dist * math.cos(math.radians(45)),
            "y": -0.25 - dist * math.sin(math.radians(45)), "yaw": 45.0 + yaw_offset_deg}


CASES = [(0.6, 0.0, 25.0), (0.8, 0.0, 15.0), (1.0, 10.0, 10.0), (1.5, -10.0, 0.0), (2.0, 0.0, 0.0)]


@pytest.mark.parametrize("size", SIZES)
@pytest.mark.parametrize(("dist", "yaw", "pitch"), CASES)
def test_corner_and_v_match_truth(scene: SceneFactory, size: tuple[int, int], dist: float,
                                  yaw: float, pitch: float) -> None:
    s = scene({"r1": corner_pose(dist, yaw)}, size=size)
    s.head(0.0, pitch)
    c = find_corner(s.image(), s.camera())
    truth = s.project(s.world.truth.table_corners()[2])      # the (-0.4, -0.25) top corner
    assert truth is not None
    px = size[0] / 160
    assert c.found and c.is_v and not c.corner_clipped
    assert c.corner[0] == pytest.approx(truth[0], abs=1.5 * px)
    assert c.corner[1] == pytest.approx(truth[1], abs=1.5 * px)
    true_corner = s.body(s.world.truth.table_corners()[2])
    assert math.hypot(c.ground.x - true_corner[0], c.ground.y - true_corner[1]) < 0.05 * dist
    # left arm: the 0.5 m short side, right arm: the 0.8 m long side
    assert c.longer == "right"
    assert c.left.length_m == pytest.approx(0.5, rel=0.16)
    if not c.right.clipped:
        assert c.right.length_m == pytest.approx(0.8, rel=0.1)
    assert c.left.angle_deg > 90 and c.right.angle_deg < 90


def test_corner_centred_when_facing_it(scene: SceneFactory) -> None:
    s = scene({"r1": corner_pose(0.8)})
    s.head(0.0, 15.0)
    c = find_corner(s.image(), s.camera())
    assert in_centre_band(c.corner[0], s.camera().width)
    s2 = scene({"r1": corner_pose(0.8, 20.0)})
    s2.head(0.0, 15.0)
    assert not in_centre_band(find_corner(s2.image(), s2.camera()).corner[0], 160)


@pytest.mark.parametrize("head_yaw", [40.0, -40.0])
def test_looking_aside_from_a_corner_sees_one_arm(scene: SceneFactory, head_yaw: float) -> None:
    s = scene({"r1": corner_pose(0.8)})
    s.head(head_yaw, 15.0)
    c = find_corner(s.image(), s.camera())
    assert c.found and c.corner_clipped and not c.is_v
    assert c.longer == ("left" if head_yaw > 0 else "right")


def test_resolutions_agree(scene: SceneFactory) -> None:
    out = []
    for size in SIZES:
        s = scene({"r1": corner_pose(1.0, 10.0)}, size=size)
        s.head(0.0, 10.0)
        out.append(find_corner(s.image(), s.camera()))
    assert out[0].ground.x == pytest.approx(out[1].ground.x, abs=0.03)
    assert out[0].ground.y == pytest.approx(out[1].ground.y, abs=0.03)
    assert out[0].corner[0] * 4 == pytest.approx(out[1].corner[0], abs=6)


class FlatCamera:
    """A stand-in camera for synthetic masks: no ground geometry."""

    width, height, cx, cy, fx, fy = 160, 120, 80.0, 60.0, 136.0, 136.0
    position = (0.0, 0.0, 0.5)

    def ray(self, u: float, v: float) -> np.ndarray:
        return np.array([1.0, 0.0, 0.0])

    def ground_point(self, u: float, v: float, plane_z: float = 0.0) -> tuple[float, float] | None:
        return None


@given(st.integers(30, 130), st.integers(50, 100), st.integers(15, 40), st.integers(15, 40))
def test_synthetic_v_vertex_recovered(apex_u: int, apex_v: int, left: int, right: int) -> None:
    top = np.zeros((120, 160), np.uint8)
    pts = np.array([[apex_u - left, apex_v - 20], [apex_u, 10], [apex_u + right, apex_v - 25],
                    [apex_u, apex_v]], np.int32)
    cv2.fillConvexPoly(top, pts, 1)
    c = corner_from_mask(top.astype(bool), FlatCamera(), DEFAULT_CONFIG)
    assert c.found and c.is_v
    assert c.corner[0] == pytest.approx(apex_u + 0.5, abs=2.0)
    assert c.corner[1] == pytest.approx(apex_v + 1.0, abs=2.0)


def test_degenerate_inputs() -> None:
    assert corner_from_mask(np.zeros((120, 160), bool), FlatCamera()) == NO_CORNER
    assert fit_line(np.array([1.0, 1.0]), np.array([2.0, 3.0])) is None
