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

from sim.perception.blobs import table_mask, to_hsv
from sim.perception.config import DEFAULT_CONFIG, Camera, PerceptionConfig


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


def top_face(image: np.ndarray, value_ratio: float = 0.9,
             cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Boolean mask of the table's top face: blue pixels near the blob's brightest value."""
    blue = table_mask(image, cfg)
    if not blue.any():
        return blue
    value = to_hsv(image)[..., 2]
    return np.asarray(blue & (value >= value_ratio * float(value[blue].max())))


def outline_points(image: np.ndarray, camera: Camera, value_ratio: float = 0.9,
                   cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Body-frame (x, y) points of the top face's visible outline, N x 2."""
    mask = top_face(image, value_ratio, cfg).astype(np.uint8)
    min_area = max(1, math.ceil(cfg.min_blob_fraction * mask.size))
    contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    h, w = mask.shape
    points: list[tuple[float, float]] = []
    for contour in contours:
        if cv2.contourArea(contour) < min_area:
            continue
        for u, v in contour.reshape(-1, 2):
            if 0 < u < w - 1 and 0 < v < h - 1:
                ground = camera.ground_point(u + 0.5, v + 0.5, cfg.table_top_height)
                if ground is not None:
                    points.append(ground)
    return np.asarray(points, dtype=float).reshape(-1, 2)


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


def table_rect(image: np.ndarray, camera: Camera, value_ratio: float = 0.9,
               cfg: PerceptionConfig = DEFAULT_CONFIG) -> TableRect:
    """The table top from a single view (a partial view gives a smaller rectangle)."""
    return fit_rect(outline_points(image, camera, value_ratio, cfg))
