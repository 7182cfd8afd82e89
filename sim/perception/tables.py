"""Every table in view, told apart, on the floor plan of the robot's odometry frame; and the
one a task names, picked by where it is.

A table's lit top face is one connected region of the image unless something stands in front
of it: so the top-face regions that another robot's pixels join are one table. Each table's
visible outline is put on the plane of the top through the camera model and moved into the
odometry frame by the pose the model carries, so views taken with other head (or body) poses
share the frame; pieces from several views that come within `table_gap` of each other are the
same table. The smallest rectangle around a table's points gives its centre, heading (the
long axis, modulo pi) and size. Two tables whose tops overlap in the image look like one.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import cv2
import numpy as np

from sim.perception.blobs import components
from sim.perception.camera import CameraModel
from sim.perception.colour import colour_mask, to_hsv, top_face
from sim.perception.config import DEFAULT_CONFIG, PerceptionConfig
from sim.perception.table_rect import TableRect, fit_rect

Point = tuple[float, float]
MAX_GAP_POINTS = 300  # outline points per piece used to measure the gap between pieces


@dataclass(frozen=True)
class TableSeen:
    """One table in the odometry frame: `rect` (x, y, heading `axis`, `length` >= `width`);
    `clipped` when its top ran out of some view (then it may be larger than `rect`)."""

    rect: TableRect
    clipped: bool

    @property
    def position(self) -> Point:
        return (self.rect.x, self.rect.y)


@dataclass(frozen=True)
class Piece:
    """Outline points (odometry frame, N x 2) of one table's top in one view."""

    points: np.ndarray
    clipped: bool


def _regions(image: np.ndarray, value_ratio: float, cfg: PerceptionConfig) -> list[np.ndarray]:
    """One mask per table in view: the top-face regions, grouped where robots join them."""
    top = top_face(image, value_ratio, cfg)
    labels, keep = components(top, cfg)
    if keep.size <= 1:
        return [labels == k for k in keep]
    hsv = to_hsv(image)
    robots = np.zeros(top.shape, bool)
    for colour in cfg.robot_colours:
        robots |= colour_mask(hsv, colour, cfg)
    _, joined = cv2.connectedComponents((top | robots).astype(np.uint8), connectivity=8)
    groups: dict[int, np.ndarray] = {}
    for k in keep:
        region = labels == k
        group = int(joined[region][0])
        groups[group] = groups[group] | region if group in groups else region
    return list(groups.values())


def pieces_in_view(image: np.ndarray, camera: CameraModel, value_ratio: float = 0.9,
                   cfg: PerceptionConfig = DEFAULT_CONFIG) -> list[Piece]:
    """One piece per table in the image (see the module docstring)."""
    h, w = image.shape[:2]
    pieces = []
    for region in _regions(image, value_ratio, cfg):
        contours, _ = cv2.findContours(region.astype(np.uint8), cv2.RETR_EXTERNAL,
                                       cv2.CHAIN_APPROX_NONE)
        us, vs = np.concatenate([c.reshape(-1, 2) for c in contours]).T
        inside = (us > 0) & (us < w - 1) & (vs > 0) & (vs < h - 1)
        body = camera.points_on_plane(us[inside] + 0.5, vs[inside] + 0.5, cfg.table_top_height)
        pieces.append(Piece(camera.to_odom(body), not bool(inside.all())))
    return pieces


def gap(a: np.ndarray, b: np.ndarray) -> float:
    """The smallest distance between two point sets (each thinned to MAX_GAP_POINTS)."""
    a = a[:: max(1, len(a) // MAX_GAP_POINTS)]
    b = b[:: max(1, len(b) // MAX_GAP_POINTS)]
    if len(a) == 0 or len(b) == 0:
        return math.inf
    return float(np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2).min()))


def group_pieces(pieces: Sequence[Piece], max_gap: float) -> list[Piece]:
    """Merge pieces within `max_gap` of each other, transitively (the same table in several
    views); the merged piece is clipped if any of its parts is."""
    groups = list(pieces)
    merged = True
    while merged:
        merged = False
        for i in range(len(groups)):
            for j in range(i + 1, len(groups)):
                if gap(groups[i].points, groups[j].points) <= max_gap:
                    a, b = groups[i], groups.pop(j)
                    groups[i] = Piece(np.concatenate([a.points, b.points]), a.clipped or b.clipped)
                    merged = True
                    break
            if merged:
                break
    return groups


def see_tables(views: Iterable[tuple[np.ndarray, CameraModel]], value_ratio: float = 0.9,
               cfg: PerceptionConfig = DEFAULT_CONFIG) -> list[TableSeen]:
    """Every table in the views (images with the camera models they were taken with), nearest
    to the last view's camera first. `value_ratio`: see `colour.top_face`."""
    views = list(views)
    pieces = [piece for image, camera in views
              for piece in pieces_in_view(image, camera, value_ratio, cfg)]
    tables = []
    for piece in group_pieces(pieces, cfg.table_gap):
        rect = fit_rect(piece.points)
        if rect.found:
            tables.append(TableSeen(rect, piece.clipped))
    if views:
        x, y, _ = views[-1][1].odom
        tables.sort(key=lambda t: math.hypot(t.rect.x - x, t.rect.y - y))
    return tables


def pick_table(tables: Sequence[TableSeen], near: Point, gate: float) -> TableSeen | None:
    """The table whose centre is nearest to `near` (odometry frame), if within `gate` metres."""
    if not tables:
        return None
    best = min(tables, key=lambda t: math.dist(t.position, near))
    return best if math.dist(best.position, near) <= gate else None
