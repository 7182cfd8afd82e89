"""What two robots carrying the table need to see (the paper's section 3.6 and Figure 6).

* `near_edge`: the down camera looking at the table's near long edge at grip distance. The
  rim's bottom (the lower end of the first blue run from the top of each column) is put on
  the plane z = table_edge_height and a line is fitted there: how far the edge is from the
  body and how much the robot must turn to stand parallel to it.
* `side_extent`: with the head turned left or right, how far the table reaches to that side
  (Behaviour 2, "look left and right to determine which side is the longest"). Every table
  pixel is put on the plane of the top; pixels that are not on the top (rim, legs) land
  nearer to the camera, so the farthest point to that side is the top's corner.
* `wall_to_side`: the floor-wall line to one side, put on the floor: how far the wall is.
  Figure 6 tests "the top edge of the table is in line with the bottom edge of the wall" in
  the image. With this camera (0.52 m) and table (0.33 m) the two lines meet in the image
  when the table's end is still ~0.6-0.8 m from the wall, and nearer than that the table
  top hides the wall's foot; so the behaviours compare them on the floor instead: the
  wall's distance minus the table's `side_extent` to that side.

Pure functions over an RGB image and the robot's own camera model; no pybullet, no truth.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import cv2
import numpy as np

from sim.perception.blobs import clean_mask, colour_hue, table_mask, to_hsv
from sim.perception.config import DEFAULT_CONFIG, Camera, PerceptionConfig


@dataclass(frozen=True)
class NearEdge:
    """The near long edge in the body frame: `distance` (m) from the body centre to the edge
    line, `turn` (rad, counter-clockwise +) that would make the shoulders parallel to it."""

    found: bool
    distance: float = math.nan
    turn: float = math.nan
    points: int = 0


@dataclass(frozen=True)
class SideExtent:
    """How far (m) the table top reaches to one side of the body (`lateral`, body y, >= 0),
    and whether the table runs out of the view on that side (then it reaches further)."""

    found: bool
    lateral: float = math.nan
    clipped: bool = False


@dataclass(frozen=True)
class WallSeen:
    """The floor-wall line to one side: `distance` (m) from the body centre to it, and `normal`
    (rad, body frame, counter-clockwise from forward): the direction from the body centre to
    its nearest point, square to the wall. A wall square to the side axis has normal +-pi/2."""

    found: bool
    distance: float = math.nan
    points: int = 0
    normal: float = math.nan


NO_EDGE, NO_EXTENT, NO_WALL = NearEdge(False), SideExtent(False), WallSeen(False)


def on_plane(camera: Camera, us: np.ndarray, vs: np.ndarray, plane_z: float
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Body-frame (x, y) where the rays through pixel coordinates (us, vs) meet z = plane_z,
    and a mask of the rays that do (downwards to a plane below the camera, or up)."""
    cam = np.stack([np.ones_like(us, dtype=float), -(us - camera.cx) / camera.fx,
                    -(vs - camera.cy) / camera.fy])
    rays = np.asarray(camera.rotation) @ cam
    px, py, pz = camera.position
    dz = plane_z - pz
    ok = rays[2] * dz > 1e-9
    t = np.where(ok, dz / np.where(ok, rays[2], 1.0), 0.0)
    return px + t * rays[0], py + t * rays[1], ok


def _first_run_bottoms(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
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


def near_edge(image: np.ndarray, camera: Camera,
              cfg: PerceptionConfig = DEFAULT_CONFIG) -> NearEdge:
    """The near long edge seen by the down camera (see the module docstring)."""
    mask, _ = clean_mask(table_mask(image, cfg), cfg)
    cols, bottoms = _first_run_bottoms(mask)
    if cols.size < max(3, cfg.min_edge_px_fraction * camera.width):
        return NO_EDGE
    xs, ys, ok = on_plane(camera, cols + 0.5, bottoms + 1.0, cfg.table_edge_height)
    if np.count_nonzero(ok) < 3:
        return NO_EDGE
    pts = np.column_stack([xs[ok], ys[ok]]).astype(np.float32)
    dx, dy, x0, y0 = (float(v) for v in cv2.fitLine(pts, cv2.DIST_HUBER, 0, 0.01, 0.01).ravel())
    if dy < 0:
        dx, dy = -dx, -dy
    distance = abs(x0 * dy - y0 * dx)
    return NearEdge(True, distance=distance, turn=-math.atan2(dx, dy), points=int(pts.shape[0]))


def side_extent(image: np.ndarray, camera: Camera, side: str, turn: float = 0.0,
                cfg: PerceptionConfig = DEFAULT_CONFIG) -> SideExtent:
    """How far the table top reaches to `side` ('left' or 'right'), measured along the near
    edge: `turn` is that edge's `NearEdge.turn` (0: the edge runs along the body's y axis)."""
    mask, _ = clean_mask(table_mask(image, cfg), cfg)
    vs, us = np.nonzero(mask)
    if us.size == 0:
        return NO_EXTENT
    xs, ys, ok = on_plane(camera, us + 0.5, vs + 0.5, cfg.table_top_height)
    if not ok.any():
        return NO_EXTENT
    sign = 1.0 if side == "left" else -1.0
    along = -math.sin(turn) * xs + math.cos(turn) * ys
    lateral = float(np.max(sign * along[ok]))
    outer = mask[:, 0] if side == "left" else mask[:, -1]
    return SideExtent(True, lateral=max(0.0, lateral), clipped=bool(outer.any()))


def floor_mask(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Floor pixels: the floor's hue at the floor's moderate saturation."""
    hsv = to_hsv(image)
    low, high = cfg.floor_saturation
    hue = colour_hue(cfg.floor_colour)
    diff = np.abs(hsv[..., 0].astype(np.int16) - hue)
    diff = np.minimum(diff, 180 - diff)
    return np.asarray((diff <= cfg.hue_tolerance) & (hsv[..., 1] >= low) & (hsv[..., 1] <= high))


def wall_mask(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Off-white wall pixels: low saturation, bright."""
    hsv = to_hsv(image)
    return np.asarray((hsv[..., 1] <= cfg.wall_max_saturation) & (hsv[..., 2] >= cfg.wall_min_value))


def floor_wall_line(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG
                    ) -> tuple[np.ndarray, np.ndarray]:
    """(u, v) pixel coordinates of the wall's bottom edge wherever floor lies right below
    it (at least `wall_min_run` wall pixels above and floor below)."""
    wall, floor = wall_mask(image, cfg), floor_mask(image, cfg)
    run = cfg.wall_min_run
    edge = wall[:-1] & floor[1:]
    us: list[float] = []
    vs: list[float] = []
    for col in np.nonzero(edge.any(axis=0))[0]:
        row = int(np.nonzero(edge[:, col])[0][-1])
        if row + 1 >= run and wall[row + 1 - run:row + 1, col].all():
            us.append(col + 0.5)
            vs.append(row + 1.0)
    return np.asarray(us), np.asarray(vs)


def wall_to_side(image: np.ndarray, camera: Camera, side: str,
                 within: tuple[float, ...] = (0.6, 1.0), min_points: int = 10,
                 cfg: PerceptionConfig = DEFAULT_CONFIG) -> WallSeen:
    """The wall on `side` ('left'/'right') of the body: the floor-wall line put on the floor,
    kept where it lies within `within[i]` rad of that side's axis (the narrowest window with
    `min_points` points: a wall seen far back may be the next wall), fitted with a line.
    `distance` is the body centre's distance to that line (m)."""
    us, vs = floor_wall_line(image, cfg)
    if us.size < 3:
        return NO_WALL
    xs, ys, ok = on_plane(camera, us, vs, 0.0)
    axis = math.pi / 2 if side == "left" else -math.pi / 2
    off = np.abs(np.angle(np.exp(1j * (np.arctan2(ys, xs) - axis))))
    for window in within:
        keep = ok & (off <= window)
        if np.count_nonzero(keep) >= max(3, min_points):
            return _wall_line(xs[keep], ys[keep])
    return NO_WALL


def _wall_line(xs: np.ndarray, ys: np.ndarray) -> WallSeen:
    pts = np.column_stack([xs, ys]).astype(np.float32)
    dx, dy, x0, y0 = (float(v) for v in cv2.fitLine(pts, cv2.DIST_HUBER, 0, 0.01, 0.01).ravel())
    offset = x0 * dy - y0 * dx  # the line is (-dy, dx) . p = -offset
    nx, ny = (dy, -dx) if offset > 0 else (-dy, dx)
    return WallSeen(True, distance=abs(offset), points=int(pts.shape[0]), normal=math.atan2(ny, nx))
