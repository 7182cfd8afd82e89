"""Test-side scene of three tables in one room (a scenario's `tables:`), with the truth to
judge by."""

from __future__ import annotations

import math

from hfsm_sim.perception import TableSeen
from hfsm_sim.scenario import scenario_from_dict
from hfsm_sim.world import World

Truth = tuple[float, float, float, float, float]
# (x, y, yaw degrees, length, width) in the world; r1 starts at (0, -1.4) facing +y
TABLES: list[Truth] = [(0.0, 0.0, 0.0, 0.8, 0.5), (-1.3, -0.5, 60.0, 1.0, 0.5),
                       (1.4, -0.6, 100.0, 0.8, 0.6)]
START = (0.0, -1.4, 90.0)


def three_tables(robots: dict[str, dict[str, float]] | None = None) -> World:
    """The world of TABLES, with r1 at START unless other robots are given."""
    robots = robots or {"r1": {"x": START[0], "y": START[1], "yaw": START[2]}}
    tables = [{"x": x, "y": y, "yaw": yaw, "length": length, "width": width}
              for x, y, yaw, length, width in TABLES]
    return World(scenario_from_dict({"room": {"width": 8.0, "depth": 8.0}, "robots": robots,
                                     "tables": tables}), 0)


def in_start_frame(x: float, y: float) -> tuple[float, float]:
    """A world point in r1's odometry frame (its start pose, while it has not walked)."""
    sx, sy, syaw = START[0], START[1], math.radians(START[2])
    c, s = math.cos(syaw), math.sin(syaw)
    return (c * (x - sx) + s * (y - sy), -s * (x - sx) + c * (y - sy))


def heading_error(a: float, b: float) -> float:
    """Difference of two long-axis directions, modulo pi (degrees)."""
    d = math.degrees(a - b) % 180.0
    return min(d, 180.0 - d)


def matches(seen: TableSeen, truth: Truth) -> bool:
    """Within what 160 x 120 pixels give 1.4 m away, the top seen at a grazing angle (a pixel
    row of the top is several cm, the heading a few degrees); sizes within the behaviours' `Look.size_tolerance`."""
    x, y, yaw, length, width = truth
    tx, ty = in_start_frame(x, y)
    r = seen.rect
    return (math.dist((r.x, r.y), (tx, ty)) < 0.08 and abs(r.length - length) < 0.1
            and abs(r.width - width) < 0.1
            and heading_error(r.axis, math.radians(yaw - START[2])) < 7.0)
