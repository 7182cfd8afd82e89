"""The down camera at the table: share of blue, and the table's near edge as a line.

At grip distance the down camera sees the table's lit top face above its near edge. The
face's lower outline is fitted as a line in the image; put through the camera model on the
plane of the top, it becomes a line in the body frame: its angle to the shoulders (the body
y axis) and its distance ahead of the robot. That is what the align and lifting-point
behaviours need (Behaviour 2's "align body parallelly to the table", within 20 degrees).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sim.perception.blobs import clean_mask, table_mask
from sim.perception.config import DEFAULT_CONFIG, Camera, PerceptionConfig, scaled
from sim.perception.corners import fit_line, outline, top_face_mask


@dataclass(frozen=True)
class DownView:
    """`blue_fraction`: share of table pixels in the image. The near edge (when
    `edge_found`): `image_angle_deg` its slope in the image (0 = level, + = rising to the
    right on screen), `edge_v` its row at the centre column; `angle_deg` the edge's angle
    to the shoulders in the body frame (0 = parallel; turning by -angle_deg, clockwise for a
    positive angle, makes the shoulders parallel); `distance` (m) the edge's x ahead of
    the robot's centre along its own axis (y = 0)."""

    blue_fraction: float
    edge_found: bool = False
    image_angle_deg: float = math.nan
    edge_v: float = math.nan
    angle_deg: float = math.nan
    distance: float = math.nan
    residual_px: float = math.nan


def _on_plane(camera: Camera, us: np.ndarray, vs: np.ndarray, z: float
              ) -> tuple[np.ndarray, np.ndarray]:
    pts = [camera.ground_point(float(u), float(v), z) for u, v in zip(us, vs, strict=True)]
    good = [p for p in pts if p is not None]
    return np.array([p[0] for p in good]), np.array([p[1] for p in good])


def down_view(image: np.ndarray, camera: Camera, cfg: PerceptionConfig = DEFAULT_CONFIG,
              table_lift: float = 0.0) -> DownView:
    """Blue share and the near edge of the table top in a down-camera image. `table_lift`:
    how far the table is above its resting height (m), e.g. while carried."""
    blue, _ = clean_mask(table_mask(image, cfg), cfg)
    fraction = float(blue.mean())
    top = top_face_mask(image, cfg)
    h, w = top.shape
    if fraction < cfg.down_min_fraction or not top.any():
        return DownView(fraction)
    cols, _, bottoms = outline(top)
    margin = scaled(cfg.fit_margin_fraction, w, 1)
    ok = (bottoms < h - 1) & (cols >= margin) & (cols < w - margin)
    us, vs = cols[ok] + 0.5, bottoms[ok] + 1.0
    fit = fit_line(us, vs) if us.size >= scaled(cfg.min_edge_px_fraction, w, 3) else None
    if fit is None:
        return DownView(fraction)
    step = max(1, us.size // cfg.max_plane_points)
    xs, ys = _on_plane(camera, us[::step], vs[::step], cfg.table_top_height + table_lift)
    body = fit_line(ys, xs)           # x = a + b * y
    if body is None:
        return DownView(fraction)
    return DownView(fraction, edge_found=True, image_angle_deg=math.degrees(math.atan(-fit[1])),
                    edge_v=fit[0] + fit[1] * w / 2, angle_deg=math.degrees(math.atan(body[1])),
                    distance=body[0], residual_px=fit[2])
