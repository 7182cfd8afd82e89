"""Straight lines on the floor plan (body frame): the robust fit the near edge and the walls use."""

from __future__ import annotations

import math
from dataclasses import dataclass

import cv2
import numpy as np


@dataclass(frozen=True)
class FloorLine:
    """A line through (x0, y0) along the unit direction (dx, dy), with dy >= 0; `distance`
    is the body centre's (the origin's) distance to it and `normal` (rad, counter-clockwise
    from forward) the direction from the body centre to its nearest point, square to it."""

    x0: float
    y0: float
    dx: float
    dy: float
    points: int

    @property
    def offset(self) -> float:
        """Signed: the line is (-dy, dx) . p = -offset."""
        return self.x0 * self.dy - self.y0 * self.dx

    @property
    def distance(self) -> float:
        return abs(self.offset)

    @property
    def normal(self) -> float:
        nx, ny = (self.dy, -self.dx) if self.offset > 0 else (-self.dy, self.dx)
        return math.atan2(ny, nx)


def fit_floor_line(xs: np.ndarray, ys: np.ndarray) -> FloorLine:
    """Robust (Huber) line through the points (at least two)."""
    pts = np.column_stack([xs, ys]).astype(np.float32)
    dx, dy, x0, y0 = (float(v) for v in cv2.fitLine(pts, cv2.DIST_HUBER, 0, 0.01, 0.01).ravel())
    if dy < 0:
        dx, dy = -dx, -dy
    return FloorLine(x0, y0, dx, dy, int(pts.shape[0]))
