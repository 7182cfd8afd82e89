"""A full body's frames: its odometry starts at zero where it was placed; the room's frame is the scenario's.

A robot is told where it was placed (`in.start`, the scenario's pose as written, not the jittered
truth): positions it says to the team are in the room's frame, positions it is given to act on
(the `table` and `toward` params of move_furniture) are in its own start frame.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any


def to_room(start: Mapping[str, Any], point: Sequence[float]) -> list[float]:
    """A point of the robot's start frame in the room's frame."""
    yaw = math.radians(float(start["yaw"]))
    x, y = float(point[0]), float(point[1])
    return [round(float(start["x"]) + math.cos(yaw) * x - math.sin(yaw) * y, 6),
            round(float(start["y"]) + math.sin(yaw) * x + math.cos(yaw) * y, 6)]


def to_local(start: Mapping[str, Any], point: Sequence[float]) -> list[float]:
    """A point of the room's frame in the robot's start frame."""
    yaw = math.radians(float(start["yaw"]))
    dx, dy = float(point[0]) - float(start["x"]), float(point[1]) - float(start["y"])
    return [round(math.cos(yaw) * dx + math.sin(yaw) * dy, 6),
            round(-math.sin(yaw) * dx + math.cos(yaw) * dy, 6)]


def ahead(pose: Mapping[str, Any], distance: float) -> list[float]:
    """The point `distance` metres in front of a pose {x, y, yaw: degrees} (in the pose's frame)."""
    yaw = math.radians(float(pose["yaw"]))
    return [float(pose["x"]) + distance * math.cos(yaw), float(pose["y"]) + distance * math.sin(yaw)]


def difficulty_of(length: float, width: float, scale: float = 0.5) -> float:
    """TARARC's d_t of a table from its size: its top's area over the area plus `scale` m^2, in (0, 1)
    (0.8 x 0.5 m: 0.44; 1.2 x 0.6 m: 0.59), so larger tables are harder whatever their count."""
    area = length * width
    return round(area / (area + scale), 6)


def at_wall(table: Mapping[str, Any], gap: float = 0.05) -> list[float]:
    """Where a table carried along its claimed way stands once at the wall (room frame): its end
    `gap` m from the wall point `toward`, on the line from its start."""
    x, y = float(table["x"]), float(table["y"])
    tx, ty = float(table["toward"][0]), float(table["toward"][1])
    span = math.hypot(tx - x, ty - y)
    back = float(table.get("length", 0.8)) / 2 + gap
    if span <= back:
        return [x, y]
    return [tx - (tx - x) / span * back, ty - (ty - y) / span * back]


def relocalise(start: Mapping[str, Any], seen: Sequence[float], heading: float, known: Sequence[float],
               yaw: float) -> dict[str, float]:
    """The start pose that puts a table seen at `seen` with its long axis at `heading` degrees (own
    frame) where it is known to stand (`known`, long axis at `yaw` degrees, room frame). A long axis
    has no direction: the turn is taken in (-90, 90]."""
    turn = (yaw - float(start["yaw"]) - heading + 90.0) % 180.0 - 90.0
    new_yaw = float(start["yaw"]) + turn
    c, s = math.cos(math.radians(new_yaw)), math.sin(math.radians(new_yaw))
    sx, sy = float(seen[0]), float(seen[1])
    return {"x": round(float(known[0]) - (c * sx - s * sy), 6),
            "y": round(float(known[1]) - (s * sx + c * sy), 6), "yaw": round(new_yaw, 6)}
