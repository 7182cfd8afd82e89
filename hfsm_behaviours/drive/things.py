"""What a humanoid's range finder tells of the things near it. Its scan is cut into segments
(neighbouring beams whose end points lie close together), each segment into straight pieces
(Douglas-Peucker); a straight piece longer than THING is a wall, every other piece is a thing (a
robot's side, robots standing close together, a lifted table's legs), told by its nearest point.
Walls are left to the planned way, which keeps off them; a table standing on the floor is below the
beams (hfsm_sim.robot.SCAN_HEIGHT)."""

from __future__ import annotations

import math

Point = tuple[float, float]
BEAMS = 90  # 4 degrees apart: a robot 1.2 m away takes two beams or more
JOIN = 0.2  # metres between neighbouring end points of one segment
STRAIGHT = 0.04  # metres off the line through a piece's ends that its points may lie
THING = 0.7  # metres: a straight piece longer end to end is a wall (two robots' sides are 0.56)


def things(ranges: list[float], look: float) -> list[Point]:
    """The nearest point, (forward, left) metres in the body frame, of each thing that the scan
    `ranges` (beam k at k/len of a turn counter-clockwise from ahead) sees within `look` metres,
    nearest first."""
    n = len(ranges)
    ends: list[Point | None] = [
        (r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)) if r < look else None
        for k, r in enumerate(ranges)]
    found = [min(piece, key=lambda q: math.hypot(*q))
             for segment in _segments(ends) for piece in _pieces(segment)
             if math.dist(piece[0], piece[-1]) <= THING]
    return sorted(found, key=lambda q: math.hypot(*q))


def _segments(ends: list[Point | None]) -> list[list[Point]]:
    """Runs of neighbouring end points (the turn wraps round) no farther than JOIN apart."""
    n = len(ends)
    first = next((k for k, e in enumerate(ends) if e is None), None)
    if first is None:  # something all round: cut where the neighbours lie farthest apart
        points = [e for e in ends if e is not None]
        first = max(range(n), key=lambda k: math.dist(points[k - 1], points[k])) - 1
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
    if current:
        segments.append(current)
    return segments


def _pieces(points: list[Point]) -> list[list[Point]]:
    """`points` split where they leave the line through the ends by more than STRAIGHT, again and
    again, into straight pieces."""
    if len(points) < 3:
        return [points]
    (ax, ay), (bx, by) = points[0], points[-1]
    length = math.hypot(bx - ax, by - ay)
    if length < 1e-9:
        offs = [math.dist(points[0], q) for q in points]
    else:
        offs = [abs((bx - ax) * (ay - qy) - (ax - qx) * (by - ay)) / length for qx, qy in points]
    worst = max(range(len(points)), key=offs.__getitem__)
    if offs[worst] <= STRAIGHT:
        return [points]
    return _pieces(points[:worst + 1]) + _pieces(points[worst:])
