"""Looking down at the table: its near long edge at grip distance (section 3.6).

The down camera sees the rim; the rim's bottom (the lower end of the first blue run from the
top of each column) is put on the plane z = table_edge_height and a line is fitted there: how
far the edge is from the body and how much the robot must turn to stand parallel to it
(Behaviour 2's "align body parallelly to the table").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hfsm_sim.perception.blobs import clean_mask
from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import table_mask
from hfsm_sim.perception.config import DEFAULT_CONFIG, PerceptionConfig
from hfsm_sim.perception.floor import fit_floor_line


@dataclass(frozen=True)
class NearEdge:
    """The near long edge in the body frame: `distance` (m) from the body centre to the edge
    line, `turn` (rad, counter-clockwise +) that would make the shoulders parallel to it."""

    found: bool
    distance: float = math.nan
    turn: float = math.nan
    points: int = 0


NO_EDGE = NearEdge(False)


def first_run_bottoms(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Columns whose first run (from the top) ends inside the image, and that end row."""
    h = mask.shape[0]
    cols = np.nonzero(mask.any(axis=0))[0]
    sub = mask[:, cols]
    tops = np.argmax(sub, axis=0)
    rows = np.arange(h)[:, None]
    gap = (rows > tops[None, :]) & ~sub
    ends = np.where(gap.any(axis=0), np.argmax(gap, axis=0), h)
    inside = ends < h
    return cols[inside], ends[inside] - 1


def near_edge(image: np.ndarray, camera: CameraModel,
              cfg: PerceptionConfig = DEFAULT_CONFIG) -> NearEdge:
    """The near long edge seen by the down camera (see the module docstring)."""
    mask, _ = clean_mask(table_mask(image, cfg), cfg)
    cols, bottoms = first_run_bottoms(mask)
    if cols.size < max(3, cfg.min_edge_px_fraction * camera.width):
        return NO_EDGE
    xs, ys, ok = camera.to_plane(cols + 0.5, bottoms + 1.0, cfg.table_edge_height)
    if np.count_nonzero(ok) < 3:
        return NO_EDGE
    line = fit_floor_line(xs[ok], ys[ok])
    return NearEdge(True, distance=line.distance, turn=-math.atan2(line.dx, line.dy),
                    points=line.points)
