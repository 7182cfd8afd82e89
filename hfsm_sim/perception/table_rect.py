"""The whole table top as a rectangle on the floor plan, from one or more views.

The lit top face is the brightest blue face (the light comes from above), so the pixels of
the table blob within `top_value_ratio` of its brightest value are the top face. The outline
of that face, put through the camera model onto the plane of the top, gives points on the
top's edges in the robot's body frame. Outline pixels on the image border are dropped (the
face goes on out of view); pixels where another body hides the face fall inside the top.
Points from several head directions merge (they share the body frame), and the smallest
rectangle holding them is the table: centre, long-axis direction, length and width.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import cv2
import numpy as np

from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import top_face
from hfsm_sim.perception.config import DEFAULT_CONFIG, PerceptionConfig


@dataclass(frozen=True)
class TableRect:
    """A table top in a plane frame: centre (x, y), `axis` the direction of the long sides
    (rad, in (-pi/2, pi/2]), `length` >= `width` (m), `points` the outline points used."""

    found: bool
    x: float = math.nan
    y: float = math.nan
    axis: float = math.nan
    length: float = 0.0
    width: float = 0.0
    points: int = 0

    def corners(self) -> list[tuple[float, float]]:
        """The four corners, counter-clockwise from (+length/2, +width/2) in the table frame."""
        c, s = math.cos(self.axis), math.sin(self.axis)
        out = []
        for a, b in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
            u, v = a * self.length / 2, b * self.width / 2
            out.append((self.x + c * u - s * v, self.y + s * u + c * v))
        return out


NO_RECT = TableRect(found=False)


def outline_pieces(image: np.ndarray, camera: CameraModel, value_ratio: float = 0.9,
                   cfg: PerceptionConfig = DEFAULT_CONFIG) -> list[tuple[np.ndarray, bool]]:
    """One piece per top-face contour that is not noise: its visible outline on the plane of
    the top (body frame, N x 2) and whether the contour ran off the image (dropped pixels)."""
    mask = top_face(image, value_ratio, cfg).astype(np.uint8)
    min_area = max(1, math.ceil(cfg.min_blob_fraction * mask.size))
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    h, w = mask.shape
    pieces = []
    for contour in contours:
        if cv2.contourArea(contour) < min_area:
            continue
        us, vs = contour.reshape(-1, 2).T
        inside = (us > 0) & (us < w - 1) & (vs > 0) & (vs < h - 1)
        points = camera.points_on_plane(us[inside] + 0.5, vs[inside] + 0.5, cfg.table_top_height)
        pieces.append((points, not bool(inside.all())))
    return pieces


def outline_points(image: np.ndarray, camera: CameraModel, value_ratio: float = 0.9,
                   cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Body-frame (x, y) points of the visible outline of every top face in view, N x 2."""
    pieces = [points for points, _ in outline_pieces(image, camera, value_ratio, cfg)]
    return np.concatenate(pieces) if pieces else np.zeros((0, 2))


def fit_rect(points: np.ndarray | Sequence[np.ndarray], min_points: int = 8) -> TableRect:
    """The smallest rectangle around the points (one array or several views' arrays)."""
    pts = points if isinstance(points, np.ndarray) else np.concatenate(list(points))
    if len(pts) < min_points:
        return NO_RECT
    (cx, cy), (a, b), angle = cv2.minAreaRect(pts.astype(np.float32))
    axis = math.radians(angle) if a >= b else math.radians(angle) + math.pi / 2
    axis = (axis + math.pi / 2) % math.pi - math.pi / 2
    return TableRect(True, float(cx), float(cy), axis, float(max(a, b)), float(min(a, b)),
                     len(pts))


def table_rect(image: np.ndarray, camera: CameraModel, value_ratio: float = 0.9,
               cfg: PerceptionConfig = DEFAULT_CONFIG) -> TableRect:
    """The table top from a single view (a partial view gives a smaller rectangle)."""
    return fit_rect(outline_points(image, camera, value_ratio, cfg))
