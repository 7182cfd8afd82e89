"""What a humanoid's range finder tells of the things near it: its scan cut into segments (neighbouring
beams whose end points lie close together), and of each segment short enough to be a robot or a
table's leg, not a wall, the nearest point. Walls are left to the planned way, which keeps off them;
a table standing on the floor is below the beams (hfsm_sim.robot.SCAN_HEIGHT)."""

from __future__ import annotations

import math

Point = tuple[float, float]
BEAMS = 90  # 4 degrees apart: a robot 1.2 m away takes two beams or more
JOIN = 0.2  # metres between neighbouring end points of one segment
THING = 0.5  # metres: a segment longer end to end is a wall


def things(ranges: list[float], look: float) -> list[Point]:
    """The nearest point, (forward, left) metres in the body frame, of each thing shorter than THING
    end to end that the scan `ranges` (beam k at k/len of a turn counter-clockwise from ahead) sees
    within `look` metres, nearest first."""
    n = len(ranges)
    ends: list[Point | None] = [
        (r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)) if r < look else None
        for k, r in enumerate(ranges)]
    if all(e is not None for e in ends):
        return []  # walled in all round: one segment, no thing
    first = next(k for k, e in enumerate(ends) if e is None)
    segments: list[list[Point]] = []
    current: list[Point] = []
    for k in range(first + 1, first + n + 1):
        end = ends[k % n]
        if end is not None and current and math.dist(current[-1], end) <= JOIN:
            current.append(end)
            continue
        if current:
            segments.append(current)
        current = [end] if end is not None else []
    found = [min(seg, key=lambda q: math.hypot(*q)) for seg in segments if math.dist(seg[0], seg[-1]) <= THING]
    return sorted(found, key=lambda q: math.hypot(*q))
