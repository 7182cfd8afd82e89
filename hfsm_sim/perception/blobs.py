"""Colour blobs: the blue table, the other robots; ground distance and bearing to a blob."""

from __future__ import annotations

import math
from dataclasses import dataclass

import cv2
import numpy as np

from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import colour_mask, table_mask, to_hsv
from hfsm_sim.perception.config import DEFAULT_CONFIG, RGB, PerceptionConfig

# Pixel coordinates are continuous as in hfsm_sim.camera: pixel (row j, column i) covers
# u in [i, i+1), v in [j, j+1). Rows and columns below are integer pixel indices.


@dataclass(frozen=True)
class Blob:
    """A colour region. `bbox` is (left, top, right, bottom) in pixel indices, inclusive.
    `lowest_row` is the index of the lowest row holding a blob pixel and `lowest_u` the
    mean continuous u of the blob pixels in that row. `touches_*`: the blob reaches that
    border of the image (it may continue outside the view)."""

    found: bool
    area_px: int = 0
    area_fraction: float = 0.0
    centroid: tuple[float, float] = (0.0, 0.0)
    bbox: tuple[int, int, int, int] = (0, 0, -1, -1)
    lowest_row: int = -1
    lowest_u: float = 0.0
    components: int = 0
    touches_left: bool = False
    touches_right: bool = False
    touches_top: bool = False
    touches_bottom: bool = False

    @property
    def left(self) -> int:
        return self.bbox[0]

    @property
    def right(self) -> int:
        return self.bbox[2]

    @property
    def top(self) -> int:
        return self.bbox[1]


NO_BLOB = Blob(found=False)


@dataclass(frozen=True)
class GroundEstimate:
    """Where a pixel's ray meets a horizontal plane, in the robot's body frame (x forward,
    y left, from the robot's centre on the floor). `distance` is the planar distance (m),
    `bearing` its direction (rad, left +). `clipped`: the blob runs off the bottom of the
    image, so the true nearest point is out of view and nearer than this estimate."""

    found: bool
    x: float = math.nan
    y: float = math.nan
    distance: float = math.nan
    bearing: float = math.nan
    pixel: tuple[float, float] = (math.nan, math.nan)
    clipped: bool = False


NO_GROUND = GroundEstimate(found=False)


def components(mask: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG
               ) -> tuple[np.ndarray, np.ndarray]:
    """Label image of the mask's 8-connected components and the labels (1..) of those that
    are not noise (at least `min_blob_fraction` of the image), after the optional opening."""
    m = np.asarray(mask, dtype=np.uint8)
    if cfg.open_kernel > 1:
        kernel = np.ones((cfg.open_kernel, cfg.open_kernel), np.uint8)
        m = np.asarray(cv2.morphologyEx(m, cv2.MORPH_OPEN, kernel), dtype=np.uint8)
    if not cv2.countNonZero(m):
        return np.zeros(m.shape, np.int32), np.zeros(0, np.int64)
    _, labels, stats, _ = cv2.connectedComponentsWithStats(m, connectivity=8)
    min_area = max(1, math.ceil(cfg.min_blob_fraction * mask.size))
    return labels, np.nonzero(stats[1:, cv2.CC_STAT_AREA] >= min_area)[0] + 1


def clean_mask(mask: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> tuple[np.ndarray, int]:
    """The union of the mask's components that are not noise, and how many they are."""
    labels, keep = components(mask, cfg)
    return np.isin(labels, keep), int(keep.size)


def blob_from_mask(mask: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> Blob:
    """The union of the mask's components that are not noise, described as a Blob."""
    clean, count = clean_mask(mask, cfg)
    m = cv2.moments(clean.astype(np.uint8), binaryImage=True)
    if m["m00"] == 0:
        return NO_BLOB
    rows = np.nonzero(clean.any(axis=1))[0]
    cols = np.nonzero(clean.any(axis=0))[0]
    h, w = mask.shape
    area = round(m["m00"])
    left, top, right, bottom = int(cols[0]), int(rows[0]), int(cols[-1]), int(rows[-1])
    return Blob(found=True, area_px=area, area_fraction=area / mask.size,
                centroid=(m["m10"] / m["m00"] + 0.5, m["m01"] / m["m00"] + 0.5),
                bbox=(left, top, right, bottom), lowest_row=bottom,
                lowest_u=float(np.nonzero(clean[bottom])[0].mean()) + 0.5, components=count,
                touches_left=left == 0, touches_right=right == w - 1, touches_top=top == 0,
                touches_bottom=bottom == h - 1)


def find_table(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> Blob:
    """The blue table's blob (all its visible parts: top and legs)."""
    return blob_from_mask(table_mask(image, cfg), cfg)


def find_robot(image: np.ndarray, colour: RGB, cfg: PerceptionConfig = DEFAULT_CONFIG) -> Blob:
    """Another robot's blob by its body colour (e.g. `cfg.robot_colours[i]`)."""
    return blob_from_mask(colour_mask(to_hsv(image), colour, cfg), cfg)


def find_robots(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> tuple[Blob, ...]:
    """One Blob per colour in `cfg.robot_colours` (found=False for robots not in view)."""
    hsv = to_hsv(image)
    return tuple(blob_from_mask(colour_mask(hsv, c, cfg), cfg) for c in cfg.robot_colours)


def find_robot_parts(image: np.ndarray, colour: RGB, cfg: PerceptionConfig = DEFAULT_CONFIG,
                     gap: int = 2) -> tuple[Blob, ...]:
    """One Blob per robot of this colour in view, apart (colours repeat beyond ten robots): the
    colour's components that are not noise, those whose columns overlap or come within `gap`
    pixels of each other taken for one robot (its limbs), left to right."""
    labels, keep = components(colour_mask(to_hsv(image), colour, cfg), cfg)
    spans = []
    for label in keep:
        cols = np.nonzero((labels == label).any(axis=0))[0]
        spans.append((int(cols[0]), int(cols[-1]), int(label)))
    groups: list[tuple[int, list[int]]] = []
    for left, right, label in sorted(spans):
        if groups and left <= groups[-1][0] + gap:
            groups[-1] = (max(groups[-1][0], right), [*groups[-1][1], label])
        else:
            groups.append((right, [label]))
    return tuple(blob_from_mask(np.isin(labels, members), cfg) for _, members in groups)


def pixel_bearing(camera: CameraModel, u: float, v: float) -> float:
    """Horizontal direction (rad, left +, body frame) of the ray through (u, v)."""
    d = camera.ray(u, v)
    return math.atan2(float(d[1]), float(d[0]))


def ground_estimate(camera: CameraModel, u: float, v: float, plane_z: float = 0.0,
                    clipped: bool = False) -> GroundEstimate:
    """Body-frame point where the ray through (u, v) meets the plane z = plane_z."""
    point = camera.ground_point(u, v, plane_z)
    if point is None:
        return NO_GROUND
    x, y = point
    return GroundEstimate(found=True, x=x, y=y, distance=math.hypot(x, y),
                          bearing=math.atan2(y, x), pixel=(u, v), clipped=clipped)


def blob_ground(blob: Blob, camera: CameraModel, plane_z: float = 0.0) -> GroundEstimate:
    """Distance and bearing to the blob's lowest pixel assumed on the floor (or on plane_z):
    the lower edge of the lowest row (v = lowest_row + 1) at the mean u of that row."""
    if not blob.found:
        return NO_GROUND
    return ground_estimate(camera, blob.lowest_u, blob.lowest_row + 1.0, plane_z,
                           clipped=blob.touches_bottom)


def table_distance(image: np.ndarray, camera: CameraModel,
                   cfg: PerceptionConfig = DEFAULT_CONFIG) -> tuple[Blob, GroundEstimate]:
    """The table blob and the ground distance/bearing to its lowest pixel (its nearest foot
    when the feet are in view; see GroundEstimate.clipped)."""
    blob = find_table(image, cfg)
    return blob, blob_ground(blob, camera)


def in_centre_band(u: float, width: int, cfg: PerceptionConfig = DEFAULT_CONFIG) -> bool:
    """Figure 5 / section 5: u within the central band, cx +- margin * width / 2
    (pixels 256..384 of 640 with the default 20 %)."""
    half = cfg.centre_margin * width / 2
    return abs(u - width / 2) <= half


def is_near(blob: Blob, height: int, cfg: PerceptionConfig = DEFAULT_CONFIG) -> bool:
    """Section 5: the table's lowest pixel is more than `near_row_fraction` down the image."""
    return blob.found and blob.lowest_row + 1 > cfg.near_row_fraction * height


def is_below(lower: Blob, upper: Blob) -> bool:
    """Section 4: 'the leader stands behind the table if the table blob is below the leader
    blob': both found, overlapping in columns, and `lower`'s centroid lower in the image."""
    if not (lower.found and upper.found):
        return False
    overlap = min(lower.right, upper.right) >= max(lower.left, upper.left)
    return overlap and lower.centroid[1] > upper.centroid[1]
