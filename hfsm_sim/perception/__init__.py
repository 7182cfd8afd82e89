"""Perception: pure functions over a robot's RGB images (H x W x 3 uint8) and its own camera
model. No pybullet, no truth.

One camera model and one projection (`camera`: intrinsics, pose from the head joints and
odometry, `CameraModel.to_plane` from image to floor); pixel classes by colour (`colour`);
small detectors on them: `blobs` (table and robot blobs, ground distance and bearing, the
paper's Figure 5 tests), `table_rect` (the table top as a rectangle on the floor plan),
`edge` (the near edge seen looking down), `reach` (how far the table reaches to one side),
`walls` (the floor-wall line), `tables` (every table in view told apart, in the odometry
frame, and the one a task names picked by where it is); `floor` (lines on the floor plan);
`config` (every threshold).
"""

from hfsm_sim.perception.blobs import (
    NO_BLOB,
    NO_GROUND,
    Blob,
    GroundEstimate,
    blob_from_mask,
    blob_ground,
    clean_mask,
    components,
    find_robot,
    find_robot_parts,
    find_robots,
    find_table,
    ground_estimate,
    in_centre_band,
    is_below,
    is_near,
    pixel_bearing,
    table_distance,
)
from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import colour_mask, floor_mask, table_mask, to_hsv, top_face, wall_mask
from hfsm_sim.perception.config import DEFAULT_CONFIG, PerceptionConfig
from hfsm_sim.perception.edge import NO_EDGE, NearEdge, near_edge
from hfsm_sim.perception.reach import NO_EXTENT, SideExtent, side_extent
from hfsm_sim.perception.table_rect import NO_RECT, TableRect, fit_rect, outline_points, table_rect
from hfsm_sim.perception.tables import TableSeen, pick_table, see_tables
from hfsm_sim.perception.walls import NO_WALL, WallSeen, floor_wall_line, wall_to_side

__all__ = [
    "DEFAULT_CONFIG",
    "NO_BLOB",
    "NO_EDGE",
    "NO_EXTENT",
    "NO_GROUND",
    "NO_RECT",
    "NO_WALL",
    "Blob",
    "CameraModel",
    "GroundEstimate",
    "NearEdge",
    "PerceptionConfig",
    "SideExtent",
    "TableRect",
    "TableSeen",
    "WallSeen",
    "blob_from_mask",
    "blob_ground",
    "clean_mask",
    "colour_mask",
    "components",
    "find_robot",
    "find_robot_parts",
    "find_robots",
    "find_table",
    "fit_rect",
    "floor_mask",
    "floor_wall_line",
    "ground_estimate",
    "in_centre_band",
    "is_below",
    "is_near",
    "near_edge",
    "outline_points",
    "pick_table",
    "pixel_bearing",
    "see_tables",
    "side_extent",
    "table_distance",
    "table_mask",
    "table_rect",
    "to_hsv",
    "top_face",
    "wall_mask",
    "wall_to_side",
]
