"""Every table in view, told apart, on the floor plan of the robot's odometry frame; and the
one a task names, picked by where it is.

A table's lit top face is one connected region of the image unless something stands in front
of it. Each region's visible outline is put on the plane of the top through the camera model
and moved into the odometry frame by the pose the model carries, so views taken with other
head (or body) poses share the frame. Two pieces are one table when a robot's pixels join
them in an image (it hides the part between) or they come within `table_gap` on the floor
(the same table in two views), and only if together they are no larger than the largest table
(`table_max_size`). The smallest rectangle around a table's points gives its centre, heading
(the long axis, modulo pi) and size. Two tables whose tops overlap in the image look like one.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import cv2
import numpy as np

from hfsm_sim.perception.blobs import components
from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import colour_mask, to_hsv, top_face
from hfsm_sim.perception.config import DEFAULT_CONFIG, PerceptionConfig
from hfsm_sim.perception.table_rect import TableRect, fit_rect

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
    """Outline points (odometry frame, N x 2) of one table's top seen in one or more views;
    `bridges`: the (view, region) labels of the image regions, top faces joined by robots'
    pixels, that its parts were seen in."""

    points: np.ndarray
    clipped: bool
    bridges: frozenset[tuple[int, int]] = frozenset()


def _bridges(image: np.ndarray, top: np.ndarray, cfg: PerceptionConfig) -> np.ndarray:
    """Labels of the regions of top faces and robots together (a robot in front of a table
    joins the parts of its top that it does not hide)."""
    hsv = to_hsv(image)
    joined = top.copy()
    for colour in cfg.robot_colours:
        joined |= colour_mask(hsv, colour, cfg)
    return np.asarray(cv2.connectedComponents(joined.astype(np.uint8), connectivity=8)[1])


def pieces_in_view(image: np.ndarray, camera: CameraModel, view: int = 0, value_ratio: float = 0.9,
                   cfg: PerceptionConfig = DEFAULT_CONFIG) -> list[Piece]:
    """One piece per top-face region of the image (not noise), labelled with its bridge."""
    top = top_face(image, value_ratio, cfg)
    labels, keep = components(top, cfg)
    bridges = _bridges(image, top, cfg) if keep.size > 1 else labels
    h, w = top.shape
    pieces = []
    for k in keep:
        region = labels == k
        contours, _ = cv2.findContours(region.astype(np.uint8), cv2.RETR_EXTERNAL,
                                       cv2.CHAIN_APPROX_NONE)
        us, vs = np.concatenate([c.reshape(-1, 2) for c in contours]).T
        inside = (us > 0) & (us < w - 1) & (vs > 0) & (vs < h - 1)
        body = camera.points_on_plane(us[inside] + 0.5, vs[inside] + 0.5, cfg.table_top_height)
        bridge = (view, int(bridges[region][0]))
        pieces.append(Piece(camera.to_odom(body), not bool(inside.all()), frozenset([bridge])))
    return pieces


def gap(a: np.ndarray, b: np.ndarray) -> float:
    """The smallest distance between two point sets (each thinned to MAX_GAP_POINTS)."""
    a = a[:: max(1, len(a) // MAX_GAP_POINTS)]
    b = b[:: max(1, len(b) // MAX_GAP_POINTS)]
    if len(a) == 0 or len(b) == 0:
        return math.inf
    return float(np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2).min()))


def same_table(a: Piece, b: Piece, cfg: PerceptionConfig) -> Piece | None:
    """The two pieces as one, if they are one table: joined in an image or within `table_gap`
    on the floor, and together no larger than the largest table (`table_max_size`)."""
    if not (a.bridges & b.bridges or gap(a.points, b.points) <= cfg.table_gap):
        return None
    points = np.concatenate([a.points, b.points])
    rect = fit_rect(points, min_points=1)
    longest, widest = cfg.table_max_size
    if rect.length > longest or rect.width > widest:
        return None
    return Piece(points, a.clipped or b.clipped, a.bridges | b.bridges)


def group_pieces(pieces: Sequence[Piece], cfg: PerceptionConfig = DEFAULT_CONFIG) -> list[Piece]:
    """Merge pieces of the same table (`same_table`), until no two are; the merged piece is
    clipped if any of its parts is."""
    groups = list(pieces)
    i = 0
    while i < len(groups):
        for j in range(i + 1, len(groups)):
            merged = same_table(groups[i], groups[j], cfg)
            if merged is not None:
                groups[i] = merged
                groups.pop(j)
                i = -1  # a grown piece may now reach one already passed
                break
        i += 1
    return groups


def see_tables(views: Iterable[tuple[np.ndarray, CameraModel]], value_ratio: float = 0.9,
               cfg: PerceptionConfig = DEFAULT_CONFIG) -> list[TableSeen]:
    """Every table in the views (images with the camera models they were taken with), nearest
    to the robot (where the last view was taken) first. `value_ratio`: see `colour.top_face`."""
    views = list(views)
    pieces = [piece for view, (image, camera) in enumerate(views)
              for piece in pieces_in_view(image, camera, view, value_ratio, cfg)]
    tables = []
    for piece in group_pieces(pieces, cfg):
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
