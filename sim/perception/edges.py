"""The floor-wall edge and the table's top (far) edge: the paper's Figure 6.

Wall and floor are told apart by colour, not grey level (the feasibility study found the
line invisible in grey): the walls are unsaturated and bright, the floor is a moderately
saturated brown. The floor-wall edge is where a wall pixel sits directly above a floor
pixel; per column that gives a row (a polyline: it bends at the room's corners).

Figure 6: carrying the table, a robot looks towards the wall; the table is at the wall when
its top edge X is in line with the floor's edge W. `wall_meet` compares, over the table's
columns, the table's top outline with the floor-wall line (fitted next to the table and
extended behind it), in pixels, and also in metres along the camera ray: the wall foot on
the floor and the table's far edge on the plane of its top.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from sim.perception.blobs import (
    NO_GROUND,
    GroundEstimate,
    clean_mask,
    colour_hue,
    ground_estimate,
    hue_lut,
    table_mask,
    to_hsv,
)
from sim.perception.config import DEFAULT_CONFIG, Camera, PerceptionConfig
from sim.perception.corners import fit_line, outline


@dataclass(frozen=True)
class FloorWall:
    """`rows[u]`: continuous v of the floor-wall edge in column u (nan where not seen).
    `line` = (a, s, rms): the robust straight fit v = a + s * u over all seen columns
    (a single wall in view is one line; with a room corner in view, see `rows`)."""

    found: bool
    rows: np.ndarray = field(default_factory=lambda: np.zeros(0), compare=False, repr=False)
    line: tuple[float, float, float] = (math.nan, math.nan, math.nan)
    seen_fraction: float = 0.0

    def v_at(self, u: float) -> float:
        """The edge's row at continuous column u from the straight fit."""
        return self.line[0] + self.line[1] * u


NO_FLOOR_WALL = FloorWall(found=False)


@dataclass(frozen=True)
class WallMeet:
    """Figure 6. `gap_px`: smallest (table top row - floor-wall row) over the table's columns
    (> 0: floor still shows between the table's edge and the wall's foot); `meets` when
    gap_px <= `meet_tolerance_px`. At that column `u`, `wall` is the wall's foot on the floor
    and `table_edge` the table's edge on the plane of its top (body frame), and
    `gap_m` = wall.distance - table_edge.distance."""

    found: bool
    meets: bool = False
    gap_px: float = math.nan
    u: float = math.nan
    wall: GroundEstimate = NO_GROUND
    table_edge: GroundEstimate = NO_GROUND
    gap_m: float = math.nan


NO_MEET = WallMeet(found=False)


def wall_floor_masks(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG
                     ) -> tuple[np.ndarray, np.ndarray]:
    """(wall, floor) boolean masks by colour."""
    hsv = to_hsv(image)
    s, v = hsv[..., 1], hsv[..., 2]
    wall = (s <= cfg.wall_max_saturation) & (v >= cfg.wall_min_value)
    lo, hi = cfg.floor_saturation
    floor = hue_lut(colour_hue(cfg.floor_colour), cfg.hue_tolerance)[hsv[..., 0]] & (s >= lo) & (s <= hi)
    return np.asarray(wall), np.asarray(floor)


def floor_wall_edge(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> FloorWall:
    """Per column, the lowest place where a wall pixel sits right above a floor pixel."""
    wall, floor = wall_floor_masks(image, cfg)
    trans = wall[:-1] & floor[1:]
    seen = trans.any(axis=0)
    if np.count_nonzero(seen) < 2:
        return NO_FLOOR_WALL
    last = trans.shape[0] - 1 - np.argmax(trans[::-1], axis=0)
    rows = np.where(seen, last + 1.0, np.nan)
    us = np.nonzero(seen)[0] + 0.5
    fit = fit_line(us, rows[seen])
    if fit is None:
        return NO_FLOOR_WALL
    return FloorWall(found=True, rows=rows, line=fit, seen_fraction=float(seen.mean()))


def table_top_outline(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG
                      ) -> tuple[np.ndarray, np.ndarray]:
    """(columns + 0.5, top rows) of the table blob: its top/far edge, per column."""
    clean, _ = clean_mask(table_mask(image, cfg), cfg)
    cols, tops, _ = outline(clean)
    return cols + 0.5, tops.astype(float)


def _local_line(fw: FloorWall, lo: float, hi: float) -> tuple[float, float]:
    """The floor-wall line fitted on seen columns next to [lo, hi] (the nearest wall)."""
    us = np.arange(fw.rows.size) + 0.5
    seen = ~np.isnan(fw.rows)
    span = max(hi - lo, 8.0)
    near = seen & (us >= lo - span) & (us <= hi + span)
    fit = fit_line(us[near], fw.rows[near]) if np.count_nonzero(near) >= 4 else None
    return (fit[0], fit[1]) if fit is not None else (fw.line[0], fw.line[1])


def wall_meet(image: np.ndarray, camera: Camera, cfg: PerceptionConfig = DEFAULT_CONFIG,
              table_lift: float = 0.0) -> WallMeet:
    """Figure 6 test (see the module docstring). `table_lift`: how far the carried table is
    above its resting height (m), for the metric gap."""
    us, tops = table_top_outline(image, cfg)
    fw = floor_wall_edge(image, cfg)
    if us.size == 0 or not fw.found:
        return NO_MEET
    a, s = _local_line(fw, float(us[0]), float(us[-1]))
    gaps = tops - (a + s * us)
    i = int(np.argmin(gaps))
    u, gap = float(us[i]), float(gaps[i])
    wall = ground_estimate(camera, u, a + s * u, 0.0)
    edge = ground_estimate(camera, u, float(tops[i]), cfg.table_top_height + table_lift)
    gap_m = wall.distance - edge.distance if wall.found and edge.found else math.nan
    return WallMeet(found=True, meets=gap <= cfg.meet_tolerance_px, gap_px=gap, u=u,
                    wall=wall, table_edge=edge, gap_m=gap_m)
