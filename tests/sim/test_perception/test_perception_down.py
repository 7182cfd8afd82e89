from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from sim.perception.down import down_view

SceneFactory = Callable[..., Any]


@pytest.mark.parametrize("size", [(160, 120), (640, 480)])
@pytest.mark.parametrize("yaw", [80.0, 90.0, 95.0, 105.0])
def test_down_edge_angle_and_distance(scene: SceneFactory, size: tuple[int, int], yaw: float) -> None:
    """At grip distance from the table's y = -0.25 long side, facing it (+-15 deg)."""
    s = scene({"r1": {"x": 0.1, "y": -0.38, "yaw": yaw}}, size=size, room={"width": 4.0, "depth": 4.0})
    d = down_view(s.image("down"), s.camera("down"))
    a = np.array(s.body((-0.3, -0.25, 0.33)))
    b = np.array(s.body((0.3, -0.25, 0.33)))
    true_angle = math.degrees(math.atan((b[0] - a[0]) / (b[1] - a[1])))
    true_x = a[0] - (b[0] - a[0]) * a[1] / (b[1] - a[1])
    assert d.edge_found and d.blue_fraction > 0.5
    assert d.angle_deg == pytest.approx(true_angle, abs=1.0)
    assert d.distance == pytest.approx(true_x, abs=0.01)
    assert math.copysign(1, d.image_angle_deg) == -math.copysign(1, d.angle_deg) or yaw == 90.0


def test_down_view_away_from_the_table(scene: SceneFactory) -> None:
    s = scene({"r1": {"x": -1.5, "y": -1.5, "yaw": 225.0}}, room={"width": 5.0, "depth": 5.0})
    d = down_view(s.image("down"), s.camera("down"))
    assert d.blue_fraction == 0.0 and not d.edge_found
