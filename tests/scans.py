"""Laser scans cast by hand, for world-free tests of what robots make of them."""

from __future__ import annotations

import math

ROOM = (12.0, 9.0)


def cast(pose: tuple[float, float, float], beams: int = 90, reach: float = 20.0,
         room: tuple[float, float] = ROOM, clutter: tuple[tuple[float, float, float], ...] = ()) -> list[float]:
    """Ranges from `pose` to the walls of `room` centred on 0, or to the nearest disc (x, y, radius)
    of `clutter` in the way."""
    x, y, yaw = pose
    out = []
    for k in range(beams):
        c, s = math.cos(yaw + 2 * math.pi * k / beams), math.sin(yaw + 2 * math.pi * k / beams)
        hits = [((room[0] / 2 if c > 0 else -room[0] / 2) - x) / c if abs(c) > 1e-9 else math.inf,
                ((room[1] / 2 if s > 0 else -room[1] / 2) - y) / s if abs(s) > 1e-9 else math.inf]
        for cx, cy, r in clutter:
            along = (cx - x) * c + (cy - y) * s
            off = abs(-(cx - x) * s + (cy - y) * c)
            if along > 0 and off < r:
                hits.append(along - math.sqrt(r * r - off * off))
        out.append(min(reach, *hits))
    return out
