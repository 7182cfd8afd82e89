"""The walls: where the floor meets them, in the image and on the floor.

Wall and floor are told apart by colour, not grey level (the feasibility study found the line
invisible in grey). The floor-wall edge is where at least `wall_min_run` wall pixels sit right
above a floor pixel. Figure 6 tests "the top edge of the table is in line with the bottom edge
of the wall" in the image; with this camera (0.52 m) and table (0.33 m) the two lines meet in
the image when the table's end is still ~0.6-0.8 m from the wall, and nearer than that the
table top hides the wall's foot; so the behaviours compare them on the floor instead: the
wall's distance (`wall_to_side`) minus the table's reach to that side (`reach.side_extent`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import floor_mask, wall_mask
from hfsm_sim.perception.config import DEFAULT_CONFIG, PerceptionConfig
from hfsm_sim.perception.floor import fit_floor_line


@dataclass(frozen=True)
class WallSeen:
    """The floor-wall line to one side: `distance` (m) from the body centre to it, and `normal`
    (rad, body frame, counter-clockwise from forward): the direction from the body centre to
    its nearest point, square to the wall. A wall square to the side axis has normal +-pi/2."""

    found: bool
    distance: float = math.nan
    points: int = 0
    normal: float = math.nan


NO_WALL = WallSeen(False)


def floor_wall_line(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG
                    ) -> tuple[np.ndarray, np.ndarray]:
    """(u, v) pixel coordinates of the wall's bottom edge, one per column where it is seen:
    the lowest row with floor right below and `wall_min_run` wall pixels above."""
    wall, floor = wall_mask(image, cfg), floor_mask(image, cfg)
    run = cfg.wall_min_run
    edge = wall[:-1] & floor[1:]
    h = edge.shape[0]
    cols = np.nonzero(edge.any(axis=0))[0]
    rows = h - 1 - np.argmax(edge[::-1, cols], axis=0)
    above = np.ones(cols.size, bool)
    for k in range(run):
        lift = rows - k
        above &= (lift >= 0) & wall[np.maximum(lift, 0), cols]
    return cols[above] + 0.5, rows[above] + 1.0


def wall_to_side(image: np.ndarray, camera: CameraModel, side: str,
                 within: tuple[float, ...] = (0.6, 1.0), min_points: int = 10,
                 cfg: PerceptionConfig = DEFAULT_CONFIG) -> WallSeen:
    """The wall on `side` ('left'/'right') of the body: the floor-wall line put on the floor,
    kept where it lies within `within[i]` rad of that side's axis (the narrowest window with
    `min_points` points: a wall seen far back may be the next wall), fitted with a line.
    `distance` is the body centre's distance to that line (m)."""
    us, vs = floor_wall_line(image, cfg)
    if us.size < 3:
        return NO_WALL
    xs, ys, ok = camera.to_plane(us, vs, 0.0)
    axis = math.pi / 2 if side == "left" else -math.pi / 2
    off = np.abs(np.angle(np.exp(1j * (np.arctan2(ys, xs) - axis))))
    for window in within:
        keep = ok & (off <= window)
        if np.count_nonzero(keep) >= max(3, min_points):
            line = fit_floor_line(xs[keep], ys[keep])
            return WallSeen(True, distance=line.distance, points=line.points, normal=line.normal)
    return NO_WALL
