"""The one camera model: image to floor (`to_plane`) and floor to image (`project`) agree,
and the odometry frame is the body frame moved by the pose the model carries."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from hfsm_sim.camera import camera_model, camera_spec
from hfsm_sim.profile import DEFAULT_BODY

angles = st.floats(-1.0, 1.0)


@given(yaw=angles, pitch=st.floats(0.05, 0.5), u=st.floats(0.0, 160.0), v=st.floats(70.0, 120.0),
       z=st.sampled_from([0.0, 0.3, 0.33]))
def test_to_plane_and_project_are_inverse(yaw: float, pitch: float, u: float, v: float, z: float) -> None:
    cam = camera_model(camera_spec("forward"), DEFAULT_BODY, (160, 120), yaw, pitch)
    xs, ys, ok = cam.to_plane(np.array([u]), np.array([v]), z)
    assert ok[0]
    back = cam.project((float(xs[0]), float(ys[0]), z))
    assert back is not None
    assert math.isclose(back[0], u, abs_tol=1e-6) and math.isclose(back[1], v, abs_tol=1e-6)
    assert cam.ground_point(u, v, z) == (float(xs[0]), float(ys[0]))


def test_rays_above_the_horizon_never_meet_the_floor() -> None:
    cam = camera_model(camera_spec("forward"), DEFAULT_BODY, (160, 120), 0.0, 0.0)
    assert cam.ground_point(80.0, 0.0) is None
    assert cam.points_on_plane(np.array([80.0, 80.0]), np.array([0.0, 119.0])).shape == (1, 2)


@given(x=st.floats(-5, 5), y=st.floats(-5, 5), yaw=st.floats(-math.pi, math.pi),
       px=st.floats(-3, 3), py=st.floats(-3, 3))
def test_odometry_frame_round_trip(x: float, y: float, yaw: float, px: float, py: float) -> None:
    cam = camera_model(camera_spec("down"), DEFAULT_BODY, (160, 120), 0.0, 0.3, (x, y, yaw))
    odom = cam.to_odom(np.array([[px, py]]))
    assert math.isclose(math.dist(odom[0], (x, y)), math.hypot(px, py), abs_tol=1e-9)
    assert np.allclose(cam.to_body(odom), [[px, py]], atol=1e-9)
