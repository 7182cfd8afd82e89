"""The one camera model: a pinhole head camera, its pose from the head joints and odometry.

Frames: the body frame has x forward, y left, z up, origin on the floor under the robot's
centre; the odometry frame is the robot's own start frame, where `odom` places the body.
Pixel coordinates are continuous with (0, 0) at the image's top-left corner, so pixel (row j,
column i) has its centre at (u, v) = (i + 0.5, j + 0.5).

Every detector goes from image to floor through `CameraModel.to_plane` (and from floor to image
through `project`); nothing else in the package does projective geometry.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

NEAR = 0.01  # m; points nearer than this along the view are behind the camera

Pose = tuple[float, float, float]


def rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def rot_y(a: float) -> np.ndarray:
    """Rotation about +y; a positive angle turns the x axis (the view) downwards."""
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


@dataclass(frozen=True)
class CameraModel:
    """Intrinsics (fx, fy, cx, cy), the camera's place in the body frame (`position`, and its
    `yaw`/`pitch` with the head joints included) and `odom`, the body's pose in the odometry
    frame when the image was taken."""

    camera: str
    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    hfov_deg: float
    vfov_deg: float
    position: tuple[float, float, float]
    yaw: float
    pitch: float
    odom: Pose = (0.0, 0.0, 0.0)

    @property
    def rotation(self) -> np.ndarray:
        """Camera-to-body rotation (camera axes: x along the view, y left, z up)."""
        return np.asarray(rot_z(self.yaw) @ rot_y(self.pitch))

    def rays(self, us: np.ndarray, vs: np.ndarray) -> np.ndarray:
        """3 x N unit directions in the body frame of the rays through pixel coordinates."""
        us, vs = np.asarray(us, dtype=float), np.asarray(vs, dtype=float)
        cam = np.stack([np.ones_like(us), -(us - self.cx) / self.fx, -(vs - self.cy) / self.fy])
        d = self.rotation @ cam.reshape(3, -1)
        return np.asarray(d / np.linalg.norm(d, axis=0))

    def ray(self, u: float, v: float) -> np.ndarray:
        """Unit direction in the body frame of the ray through pixel coordinate (u, v)."""
        return self.rays(np.array([u]), np.array([v]))[:, 0]

    def to_plane(self, us: np.ndarray, vs: np.ndarray, plane_z: float = 0.0
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Body-frame (x, y) where the rays through (us, vs) meet the plane z = plane_z, and a
        mask of the rays that do meet it (in front of the camera)."""
        d = self.rays(us, vs)
        px, py, pz = self.position
        dz = plane_z - pz
        ok = d[2] * dz > 1e-9
        t = np.where(ok, dz / np.where(ok, d[2], 1.0), 0.0)
        return px + t * d[0], py + t * d[1], ok

    def ground_point(self, u: float, v: float, plane_z: float = 0.0) -> tuple[float, float] | None:
        """`to_plane` for one pixel coordinate; None when its ray does not meet the plane."""
        xs, ys, ok = self.to_plane(np.array([u]), np.array([v]), plane_z)
        return (float(xs[0]), float(ys[0])) if ok[0] else None

    def points_on_plane(self, us: np.ndarray, vs: np.ndarray, plane_z: float = 0.0) -> np.ndarray:
        """N x 2 body-frame points of the pixel coordinates whose rays meet the plane."""
        xs, ys, ok = self.to_plane(us, vs, plane_z)
        return np.column_stack([xs[ok], ys[ok]]).reshape(-1, 2)

    def project(self, point: tuple[float, float, float]) -> tuple[float, float] | None:
        """Pixel coordinate of a body-frame point, or None if it is behind the camera."""
        c = self.rotation.T @ (np.asarray(point, dtype=float) - np.asarray(self.position))
        if c[0] <= NEAR:
            return None
        return (self.cx - self.fx * c[1] / c[0], self.cy - self.fy * c[2] / c[0])

    def to_odom(self, points: np.ndarray) -> np.ndarray:
        """N x 2 body-frame points in the odometry frame (with the body at `odom`)."""
        x, y, yaw = self.odom
        c, s = math.cos(yaw), math.sin(yaw)
        pts = np.asarray(points, dtype=float).reshape(-1, 2)
        return np.column_stack([x + c * pts[:, 0] - s * pts[:, 1], y + s * pts[:, 0] + c * pts[:, 1]])

    def to_body(self, points: np.ndarray) -> np.ndarray:
        """N x 2 odometry-frame points in the body frame (the inverse of `to_odom`)."""
        x, y, yaw = self.odom
        c, s = math.cos(yaw), math.sin(yaw)
        pts = np.asarray(points, dtype=float).reshape(-1, 2)
        dx, dy = pts[:, 0] - x, pts[:, 1] - y
        return np.column_stack([c * dx + s * dy, -s * dx + c * dy])
