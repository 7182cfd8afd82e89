"""NAO-sized body, motion and camera profile shared by the robot, the cameras and the docs.

Numbers follow the Aldebaran NAO H25 (height 0.574 m, mass 5.4 kg, walk ~0.1 m/s forward,
~0.05 m/s sideways, ~0.5 rad/s turning; head yaw +-119.5 deg, pitch -38.5..+29.5 deg;
cameras 60.9 x 47.6 deg, bottom camera pitched 39.7 deg down).
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class MotionProfile:
    """Speed limits (m/s, rad/s) and joint ranges a robot's commands are clamped to."""

    forward_max: float = 0.10
    backward_max: float = 0.06
    sideways_max: float = 0.05
    turn_max: float = 0.5
    head_yaw_max: float = math.radians(119.5)
    head_pitch_min: float = math.radians(-38.5)
    head_pitch_max: float = math.radians(29.5)
    head_speed: float = 2.0
    arm_low: float = 0.20
    arm_high: float = 0.50
    arm_speed: float = 0.10


@dataclass(frozen=True)
class BodyGeometry:
    """Robot body in its base frame: x forward, y left, z up from the floor."""

    mass: float = 5.4
    hover: float = 0.003
    half_depth: float = 0.06
    half_width: float = 0.14
    neck_height: float = 0.46
    head_size: float = 0.12
    height: float = 0.58
    hand_x: float = 0.17
    hand_y: float = 0.10
    arm_thickness: float = 0.04
    base_max_force: float = 120.0
    hand_max_force: float = 30.0


@dataclass(frozen=True)
class CameraSpec:
    """One head camera: offset from the head pitch joint (x forward, z up) and mount pitch."""

    name: str
    x: float
    z: float
    pitch_deg: float
    hfov_deg: float = 60.9
    vfov_deg: float = 47.6


CAMERAS: dict[str, CameraSpec] = {
    "forward": CameraSpec("forward", x=0.0587, z=0.0636, pitch_deg=0.0),
    "down": CameraSpec("down", x=0.0507, z=0.0115, pitch_deg=39.7),
}

ROBOT_COLOURS: tuple[tuple[float, float, float], ...] = (
    (1.00, 0.50, 0.05),
    (0.10, 0.70, 0.20),
    (0.60, 0.20, 0.70),
    (0.90, 0.85, 0.10),
    (0.85, 0.10, 0.10),
    # rooms of several pairs (issue 10): five more hues, each at least 14 OpenCV hue units (the
    # spacing of the first three) from every other and from the table's blue (115)
    (0.51, 0.85, 0.13),
    (0.13, 0.85, 0.61),
    (0.13, 0.75, 0.85),
    (0.85, 0.13, 0.61),
    (0.37, 0.13, 0.85),
)
TABLE_COLOUR: tuple[float, float, float] = (0.05, 0.20, 0.90)
FLOOR_COLOUR: tuple[float, float, float] = (0.42, 0.32, 0.24)
WALL_COLOUR: tuple[float, float, float] = (0.92, 0.91, 0.86)

DEFAULT_MOTION = MotionProfile()
DEFAULT_BODY = BodyGeometry()
