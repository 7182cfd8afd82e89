"""Plane geometry in the robot's odometry frame: poses, the body frame, a table's sides."""

from __future__ import annotations

import math
from dataclasses import dataclass

from hfsm_sim.perception.table_rect import TableRect

Point = tuple[float, float]
Pose = tuple[float, float, float]


def wrap(angle: float) -> float:
    return (angle + math.pi) % (2 * math.pi) - math.pi


def body_to_odom(pose: Pose, point: Point) -> Point:
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    return (x + c * point[0] - s * point[1], y + s * point[0] + c * point[1])


def odom_to_body(pose: Pose, point: Point) -> Point:
    x, y, yaw = pose
    c, s = math.cos(yaw), math.sin(yaw)
    dx, dy = point[0] - x, point[1] - y
    return (c * dx + s * dy, -s * dx + c * dy)


def bearing_to(pose: Pose, point: Point) -> float:
    bx, by = odom_to_body(pose, point)
    return math.atan2(by, bx)


def distance(a: Point, b: Point) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


@dataclass(frozen=True)
class Side:
    """One side of a table: its middle, outward unit normal, unit direction, length."""

    middle: Point
    normal: Point
    along: Point
    length: float

    def standoff(self, gap: float) -> Point:
        """The point `gap` metres out from the middle of the side."""
        return (self.middle[0] + gap * self.normal[0], self.middle[1] + gap * self.normal[1])

    def facing(self) -> float:
        """The heading that faces the table across this side."""
        return math.atan2(-self.normal[1], -self.normal[0])

    def offset(self, point: Point) -> tuple[float, float]:
        """(along, out) of a point from the side's middle."""
        dx, dy = point[0] - self.middle[0], point[1] - self.middle[1]
        return (dx * self.along[0] + dy * self.along[1], dx * self.normal[0] + dy * self.normal[1])


def sides(rect: TableRect) -> list[Side]:
    """The four sides: the two long ones first."""
    c, s = math.cos(rect.axis), math.sin(rect.axis)
    out = []
    for nx, ny, half, length in ((0, 1, rect.width / 2, rect.length), (0, -1, rect.width / 2, rect.length),
                                 (1, 0, rect.length / 2, rect.width), (-1, 0, rect.length / 2, rect.width)):
        normal = (c * nx - s * ny, s * nx + c * ny)
        middle = (rect.x + half * normal[0], rect.y + half * normal[1])
        out.append(Side(middle, normal, (-normal[1], normal[0]), length))
    return out


def nearest_side(rect: TableRect, point: Point, long_only: bool = True) -> Side:
    candidates = sides(rect)[:2] if long_only else sides(rect)
    return min(candidates, key=lambda side: distance(side.middle, point))


def table_frame(rect: TableRect, point: Point) -> Point:
    """A point in the table's own frame (x along the long axis)."""
    return odom_to_body((rect.x, rect.y, rect.axis), point)


def from_table_frame(rect: TableRect, point: Point) -> Point:
    return body_to_odom((rect.x, rect.y, rect.axis), point)
