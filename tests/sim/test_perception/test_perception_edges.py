from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from sim.perception import PerceptionConfig
from sim.perception.edges import NO_FLOOR_WALL, floor_wall_edge, table_top_outline, wall_meet

SceneFactory = Callable[..., Any]
SIZES = [(160, 120), (640, 480)]
ROOM = {"width": 6.0, "depth": 6.0}          # the +x wall's face is at x = 3
WALL_X = 3.0


def make(scene: SceneFactory, gap: float, size: tuple[int, int], pitch: float = 0.0,
         robot_x: float = 0.5) -> Any:
    """Table turned across (long sides along y), `gap` m from the +x wall; the robot
    (2.5 m from that wall) looks at it over the table (the wall's foot shows beside it)."""
    s = scene({"r1": {"x": robot_x, "y": 0.05, "yaw": 0.0}}, size=size, room=ROOM,
              table={"x": WALL_X - 0.25 - gap, "y": 0.0, "yaw": 90.0})
    s.head(0.0, pitch)
    return s


@pytest.mark.parametrize("size", SIZES)
def test_floor_wall_edge_where_truth_projects_it(scene: SceneFactory, size: tuple[int, int]) -> None:
    s = make(scene, 0.8, size)
    fw = floor_wall_edge(s.image())
    assert fw.found
    a = s.project((WALL_X, -1.0, 0.0))
    b = s.project((WALL_X, 1.0, 0.0))
    assert a is not None and b is not None
    px = size[0] / 160
    for u in (0.1 * size[0], 0.9 * size[0]):          # columns beside the table
        truth_v = a[1] + (b[1] - a[1]) * (u - a[0]) / (b[0] - a[0])
        assert fw.rows[int(u)] == pytest.approx(truth_v, abs=1.0 * px)
        assert fw.v_at(u) == pytest.approx(truth_v, abs=1.0 * px)


@pytest.mark.parametrize("size", SIZES)
@pytest.mark.parametrize("gap", [1.0, 0.5, 0.2])
def test_metric_gap_to_wall(scene: SceneFactory, size: tuple[int, int], gap: float) -> None:
    s = make(scene, gap, size)
    m = wall_meet(s.image(), s.camera())
    assert m.found
    per_px = 0.09 * 160 / size[0]      # metres per pixel row at the wall's foot, 2.5 m away
    assert m.gap_m == pytest.approx(gap, abs=0.03 + 1.5 * per_px)
    assert m.wall.x == pytest.approx(WALL_X - 0.5, abs=0.03 + 1.5 * per_px)


def test_meet_flips_as_the_gap_closes(scene: SceneFactory) -> None:
    """Figure 6 in pixels. With the cameras at ~0.5 m and the top at 0.33 m, the table's far
    edge covers the wall's foot long before it reaches the wall: seen from 3.5 m, from
    ~2.2 m out (0.635 x the wall's distance)."""
    s_far = make(scene, 2.6, (160, 120), pitch=10.0, robot_x=-0.5)
    s_near = make(scene, 2.0, (160, 120), robot_x=-0.5)
    far = wall_meet(s_far.image(), s_far.camera())
    near = wall_meet(s_near.image(), s_near.camera())
    assert far.found and not far.meets and far.gap_px > 2
    assert near.found and near.meets


def test_table_top_outline_matches_far_edge(scene: SceneFactory) -> None:
    s = make(scene, 0.8, (640, 480))
    us, tops = table_top_outline(s.image())
    x_far = WALL_X - 0.8
    a, b = s.project((x_far, -0.2, 0.33)), s.project((x_far, 0.2, 0.33))
    assert a is not None and b is not None
    for u, v in ((a[0], a[1]), (b[0], b[1])):
        i = int(np.argmin(np.abs(us - u)))
        assert tops[i] == pytest.approx(v, abs=2.0)


def test_no_floor_wall_in_a_blank_image() -> None:
    assert floor_wall_edge(np.zeros((120, 160, 3), np.uint8)) == NO_FLOOR_WALL
    assert not wall_meet(np.zeros((120, 160, 3), np.uint8), None).found  # type: ignore[arg-type]
    assert PerceptionConfig().meet_tolerance_px > 0
    assert math.isfinite(PerceptionConfig().table_top_height)
