"""Perception: pure functions over a robot's RGB images (H x W x 3 uint8) and its own
camera model (`sim.CameraModel`: intrinsics, mounting, head joints). No pybullet, no truth.

Modules: `config` (PerceptionConfig, every threshold), `blobs` (table/robot blobs, ground
distance and bearing).
"""

from sim.perception.blobs import (
    NO_BLOB,
    NO_GROUND,
    Blob,
    GroundEstimate,
    blob_from_mask,
    blob_ground,
    colour_mask,
    find_robot,
    find_robots,
    find_table,
    ground_estimate,
    in_centre_band,
    is_below,
    is_near,
    pixel_bearing,
    table_distance,
    table_mask,
    to_hsv,
)
from sim.perception.config import DEFAULT_CONFIG, Camera, PerceptionConfig

__all__ = [
    "DEFAULT_CONFIG",
    "NO_BLOB",
    "NO_GROUND",
    "Blob",
    "Camera",
    "GroundEstimate",
    "PerceptionConfig",
    "blob_from_mask",
    "blob_ground",
    "colour_mask",
    "find_robot",
    "find_robots",
    "find_table",
    "ground_estimate",
    "in_centre_band",
    "is_below",
    "is_near",
    "pixel_bearing",
    "table_distance",
    "table_mask",
    "to_hsv",
]
