"""The table's near corner and its two near edges: the V of the paper's Figure 5.

The cameras (~0.5 m) look down on the top (0.33 m), and the lit top face is the brightest
blue face (`top_face_min_value`), so it is separated from the rim and the legs by its
value. The top face is a convex quadrilateral; its lower outline is the pair of near edges,
a V whose vertex is the nearest corner. We fit a line to each arm of that outline and
intersect them. Through the camera model the corner and the arm ends are put on the plane
of the top (`table_top_height`), which gives metric lengths: the long side test of
section 4 ("look left and right to determine the longer side").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import cv2
import numpy as np

from sim.perception.blobs import (
    NO_GROUND,
    GroundEstimate,
    clean_mask,
    ground_estimate,
    table_mask,
    to_hsv,
)
from sim.perception.config import DEFAULT_CONFIG, Camera, PerceptionConfig, scaled


@dataclass(frozen=True)
class Edge:
    """A straight table edge in the image, from `start` (the corner end) to `end` (pixel
    coordinates). `angle_deg` is its direction from start to end, counter-clockwise from
    the image's +u axis as seen on screen (v grows downwards). `length_m` is the distance
    between its ends on the plane z = table_top_height (nan if not projectable);
    `clipped`: the end lies on the image border, so the edge goes on out of view."""

    found: bool
    start: tuple[float, float] = (math.nan, math.nan)
    end: tuple[float, float] = (math.nan, math.nan)
    angle_deg: float = math.nan
    length_px: float = 0.0
    length_m: float = math.nan
    clipped: bool = False
    residual_px: float = math.nan


NO_EDGE = Edge(found=False)


@dataclass(frozen=True)
class TableCorner:
    """The near corner (the V's vertex) and its two arms. `is_v`: both arms were found and
    slope the V way (left arm down to the right, right arm up to the right). `longer` is
    'left' or 'right' by metric length when both are known (else by pixels), '' if no arm.
    `ground` is the corner on the plane of the rim (body frame). `corner_clipped`: only one
    arm is visible and the corner is where it leaves the view."""

    found: bool
    corner: tuple[float, float] = (math.nan, math.nan)
    left: Edge = NO_EDGE
    right: Edge = NO_EDGE
    is_v: bool = False
    longer: str = ""
    ground: GroundEstimate = NO_GROUND
    corner_clipped: bool = False


NO_CORNER = TableCorner(found=False)


def outline(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per column holding the mask: (columns, first rows, last rows)."""
    cols = np.nonzero(mask.any(axis=0))[0]
    sub = mask[:, cols]
    tops = np.argmax(sub, axis=0)
    bottoms = mask.shape[0] - 1 - np.argmax(sub[::-1], axis=0)
    return cols, tops, bottoms


def top_face_mask(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """The table top's lit upper face: table pixels at least `top_face_min_value` bright."""
    clean, _ = clean_mask(table_mask(image, cfg), cfg)
    return np.asarray(clean & (to_hsv(image)[..., 2] >= cfg.top_face_min_value))


def fit_line(us: np.ndarray, vs: np.ndarray) -> tuple[float, float, float] | None:
    """Robust (Huber) fit v = a + s * u; returns (a, s, rms residual) or None."""
    if us.size < 2 or np.ptp(us) == 0:
        return None
    pts = np.column_stack([us, vs]).astype(np.float32)
    dx, dy, x0, y0 = (float(x) for x in cv2.fitLine(pts, cv2.DIST_HUBER, 0, 0.01, 0.01).ravel())
    if abs(dx) < 1e-6:
        return None
    s = dy / dx
    a = y0 - s * x0
    return a, s, float(np.sqrt(np.mean((vs - (a + s * us)) ** 2)))


def _edge(camera: Camera, start: tuple[float, float], end: tuple[float, float], clipped: bool,
          residual: float, cfg: PerceptionConfig) -> Edge:
    du, dv = end[0] - start[0], end[1] - start[1]
    g0 = camera.ground_point(*start, cfg.table_top_height)
    g1 = camera.ground_point(*end, cfg.table_top_height)
    length_m = math.dist(g0, g1) if g0 is not None and g1 is not None else math.nan
    return Edge(found=True, start=start, end=end, angle_deg=math.degrees(math.atan2(-dv, du)),
                length_px=math.hypot(du, dv), length_m=length_m, clipped=clipped,
                residual_px=residual)


def _arm(us: np.ndarray, vs: np.ndarray, lo: float, hi: float, min_px: int
         ) -> tuple[float, float, float] | None:
    keep = (us >= lo) & (us <= hi)
    if np.count_nonzero(keep) < min_px:
        return None
    return fit_line(us[keep], vs[keep])


def _longer(left: Edge, right: Edge) -> str:
    if not (left.found or right.found):
        return ""
    if not right.found:
        return "left"
    if not left.found:
        return "right"
    if math.isfinite(left.length_m) and math.isfinite(right.length_m):
        return "left" if left.length_m >= right.length_m else "right"
    return "left" if left.length_px >= right.length_px else "right"


def corner_from_mask(top: np.ndarray, camera: Camera,
                     cfg: PerceptionConfig = DEFAULT_CONFIG) -> TableCorner:
    """The V of Figure 5 from a mask of the table's top face (see the module docstring)."""
    h, w = top.shape
    cols, _, bottoms = outline(top)
    ok = bottoms < h - 1                     # columns whose face runs off the bottom: unknown
    if np.count_nonzero(ok) < 2:
        return NO_CORNER
    k = scaled(cfg.fit_margin_fraction, w, 2)
    us, vs = cols[ok] + 0.5, bottoms[ok] + 1.0
    apex_u = float(np.mean(us[vs >= vs.max() - 0.5]))
    left_end, right_end = float(us[0] - 0.5), float(us[-1] + 0.5)
    min_px = scaled(cfg.min_edge_px_fraction, w, 3)
    lfit = _arm(us, vs, left_end + k, apex_u - k, min_px)
    rfit = _arm(us, vs, apex_u + k, right_end - k, min_px)
    return _assemble(camera, lfit, rfit, (left_end, right_end, apex_u), cfg)


def _assemble(camera: Camera, lfit: tuple[float, float, float] | None,
              rfit: tuple[float, float, float] | None, ends: tuple[float, float, float],
              cfg: PerceptionConfig) -> TableCorner:
    left_end, right_end, apex_u = ends
    if lfit is None and rfit is None:
        return NO_CORNER
    if lfit is not None and rfit is not None and abs(lfit[1] - rfit[1]) > 1e-6:
        cu = (rfit[0] - lfit[0]) / (lfit[1] - rfit[1])
        clipped = False
    else:
        cu = apex_u
        clipped = True
    fit = lfit if lfit is not None else rfit
    assert fit is not None
    corner = (cu, fit[0] + fit[1] * cu)
    w = camera.width
    left = NO_EDGE if lfit is None else _edge(
        camera, corner, (left_end, lfit[0] + lfit[1] * left_end), left_end <= 0.5, lfit[2], cfg)
    right = NO_EDGE if rfit is None else _edge(
        camera, corner, (right_end, rfit[0] + rfit[1] * right_end), right_end >= w - 0.5,
        rfit[2], cfg)
    is_v = (lfit is not None and rfit is not None and lfit[1] > cfg.v_min_slope
            and rfit[1] < -cfg.v_min_slope)
    return TableCorner(found=True, corner=corner, left=left, right=right, is_v=is_v,
                       longer=_longer(left, right),
                       ground=ground_estimate(camera, *corner, cfg.table_top_height),
                       corner_clipped=clipped)


def find_corner(image: np.ndarray, camera: Camera,
                cfg: PerceptionConfig = DEFAULT_CONFIG) -> TableCorner:
    """The table's near corner and its two edges (Figure 5) in an RGB image."""
    return corner_from_mask(top_face_mask(image, cfg), camera, cfg)
