"""Perception: pure functions over a robot's RGB images (H x W x 3 uint8) and its own
camera model (`sim.CameraModel`: intrinsics, mounting, head joints). No pybullet, no truth.

Modules: `config` (PerceptionConfig, every threshold), `blobs` (table/robot blobs, ground
distance and bearing), `corners` (the V of Figure 5, long side test), `edges` (floor-wall edge,
table top edge, Figure 6), `down` (the down camera: blue share, near edge
angle and distance for aligning).
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
from sim.perception.corners import NO_CORNER, NO_EDGE, Edge, TableCorner, find_corner, top_face_mask
from sim.perception.down import DownView, down_view
from sim.perception.edges import (
    NO_FLOOR_WALL,
    NO_MEET,
    FloorWall,
    WallMeet,
    floor_wall_edge,
    table_top_outline,
    wall_meet,
)

__all__ = [
    "DEFAULT_CONFIG",
    "NO_BLOB",
    "NO_CORNER",
    "NO_EDGE",
    "NO_FLOOR_WALL",
    "NO_GROUND",
    "NO_MEET",
    "Blob",
    "Camera",
    "DownView",
    "Edge",
    "FloorWall",
    "GroundEstimate",
    "PerceptionConfig",
    "TableCorner",
    "WallMeet",
    "blob_from_mask",
    "blob_ground",
    "colour_mask",
    "down_view",
    "find_corner",
    "find_robot",
    "find_robots",
    "find_table",
    "floor_wall_edge",
    "ground_estimate",
    "in_centre_band",
    "is_below",
    "is_near",
    "pixel_bearing",
    "table_distance",
    "table_mask",
    "table_top_outline",
    "to_hsv",
    "top_face_mask",
    "wall_meet",
]
