from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from hfsm_sim.perception import floor_wall_line, wall_to_side

SceneFactory = Callable[..., Any]
SIZES = [(160, 120), (640, 480)]
ROOM = {"width": 6.0, "depth": 6.0}          # the +x wall's face is at x = 3
WALL_X = 3.0


def make(scene: SceneFactory, gap: float, size: tuple[int, int], yaw: float = 0.0) -> Any:
    """Table turned across (long sides along y), `gap` m from the +x wall; the robot
    (2.5 m from that wall) looks at it over the table (the wall's foot shows beside it)."""
    s = scene({"r1": {"x": 0.5, "y": 0.05, "yaw": yaw}}, size=size, room=ROOM,
              table={"x": WALL_X - 0.25 - gap, "y": 0.0, "yaw": 90.0})
    s.head(0.0, 0.0)
    return s


@pytest.mark.parametrize("size", SIZES)
def test_floor_wall_line_where_truth_projects_it(scene: SceneFactory, size: tuple[int, int]) -> None:
    s = make(scene, 0.8, size)
    us, vs = floor_wall_line(s.image())
    a = s.project((WALL_X, -1.0, 0.0))
    b = s.project((WALL_X, 1.0, 0.0))
    assert a is not None and b is not None
    px = size[0] / 160
    for u in (0.1 * size[0], 0.9 * size[0]):          # columns beside the table
        truth_v = a[1] + (b[1] - a[1]) * (u - a[0]) / (b[0] - a[0])
        i = int(np.argmin(np.abs(us - u)))
        assert abs(us[i] - u) < 1.0
        assert vs[i] == pytest.approx(truth_v, abs=1.0 * px)


@pytest.mark.parametrize("size", SIZES)
def test_wall_to_the_left_of_a_robot_facing_along_it(scene: SceneFactory, size: tuple[int, int]) -> None:
    """Facing -y, the +x wall (2.5 m away) is on the robot's left; the head turned left."""
    s = make(scene, 0.8, size, yaw=-90.0)
    s.head(80.0, 10.0)
    seen = wall_to_side(s.image(), s.camera(), "left")
    assert seen.found
    assert seen.distance == pytest.approx(WALL_X - 0.5, abs=0.05)
    assert seen.normal == pytest.approx(math.pi / 2, abs=0.03)       # square to the side axis


def test_no_wall_in_a_blank_image(scene: SceneFactory) -> None:
    blank = np.zeros((120, 160, 3), np.uint8)
    us, vs = floor_wall_line(blank)
    assert us.size == 0 and vs.size == 0
    s = make(scene, 0.8, (160, 120))
    assert not wall_to_side(blank, s.camera(), "left").found
