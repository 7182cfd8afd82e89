"""Steering round what a robot senses near it (its proximity sensor): slide past each thing, never
towards one, and, when that leaves it wedged, a detour across the way it wants to go."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from hfsm_behaviours.drive.things import BEAMS, things

Point = tuple[float, float]
Near = list[tuple[float, float, float]]
JAMMED_S, DETOUR_S = 1.0, 2.0
STALLED_S, PROGRESS = 10.0, 0.3  # no PROGRESS metres nearer the goal in STALLED_S seconds: stalled
CLOSING = 4.0  # m/s of approach allowed per metre a thing sensed is beyond the clearance
SCAN_EVERY = 0.25  # seconds between a range finder's scans (a NAO's sonars read at ~10 Hz)


@dataclass
class Detour:
    """A robot slowed to a crawl by what it senses for JAMMED_S seconds, or stalled (it comes no
    PROGRESS metres nearer its goal in STALLED_S seconds: rocking in and out of the clearance of
    things standing between it and its goal, which the crawl test misses), heads across its way
    (to the side with less near it the first time, then always that side) for DETOUR_S seconds,
    twice that the second time, and so on, still dodging: a way out of the wedges that sliding
    alone never leaves (a bug-style escape, deterministic)."""

    slow_since: float | None = None
    until: float = -1.0
    way: Point = (0.0, 0.0)
    side: float = 0.0  # 1: left of the way it wants to go, -1: right; kept once chosen
    detours: int = 0
    best: float = math.inf  # the nearest to its goal it has come, and when
    best_at: float = 0.0

    def steer(self, now: float, wanted: Point, seen: list[Point], clearance: float, speed: float,
              left: float | None = None) -> Point:
        """The velocity (room frame) to command now instead of `wanted`; `left`: metres to the goal."""
        if left is not None and left < self.best - PROGRESS:
            self.best, self.best_at = left, now
        if now < self.until:
            return dodge(self.way, seen, clearance, speed)
        got = dodge(wanted, seen, clearance, speed)
        if left is not None and now - self.best_at >= STALLED_S:
            self.best_at = now
            self._across(now, wanted, seen, speed)
            return dodge(self.way, seen, clearance, speed)
        if math.hypot(*got) >= 0.25 * math.hypot(*wanted):
            self.slow_since = None
            return got
        if self.slow_since is None:
            self.slow_since = now
        elif now - self.slow_since >= JAMMED_S:
            self._across(now, wanted, seen, speed)
        return got

    def _across(self, now: float, wanted: Point, seen: list[Point], speed: float) -> None:
        pace = math.hypot(*wanted) or 1e-9
        left = (-wanted[1] / pace * speed, wanted[0] / pace * speed)
        if self.side == 0.0:
            self.side = -1.0 if sum(left[0] * ox + left[1] * oy for ox, oy in seen) > 0 else 1.0
        self.way = (left[0] * self.side, left[1] * self.side)
        self.detours += 1
        self.until, self.slow_since = now + DETOUR_S * self.detours, None


def dodge(velocity: Point, seen: list[Point], clearance: float, speed: float) -> Point:
    """`velocity` (room frame) braked towards what is seen beyond the clearance (`brake`), then bent
    around the obstacles `seen` (points relative to the robot, room frame) nearer than `clearance`:
    a slide past each (`_side`), faster the nearer it is, then no motion towards any (none at all
    when that cannot be had). At most `speed` m/s."""
    velocity = brake(velocity, seen, clearance)
    near = []
    for ox, oy in seen:
        gap = math.hypot(ox, oy)
        if 1e-9 < gap < clearance:
            near.append((ox / gap, oy / gap, (clearance - gap) / clearance))
    vx, vy = velocity
    for ux, uy, close in near:
        side = _side(ux, uy, near, velocity)
        vx, vy = vx + (side * uy - ux * close) * speed * close, vy + (-side * ux - uy * close) * speed * close
    vx, vy = _away_from(near, vx, vy)
    if near and math.hypot(vx, vy) < 0.05 * speed:  # wedged: back off the nearest, to its right
        ux, uy, _close = max(near, key=lambda n: n[2])
        vx, vy = _away_from(near, (uy - ux) * speed / 2, (-ux - uy) * speed / 2)
    pace = math.hypot(vx, vy)
    return (vx / pace * speed, vy / pace * speed) if pace > speed else (vx, vy)


def brake(velocity: Point, seen: list[Point], clearance: float) -> Point:
    """`velocity` with its approach to each thing `seen` beyond `clearance` (gap metres away) at most
    CLOSING * (gap - clearance) m/s: a robot closes on what it senses no faster than it can stop at
    the clearance within 1/CLOSING s, whatever its top speed, so that two robots crossing fast, each
    braking so, never cover the clearance in a tick or two (sliding past stays free)."""
    vx, vy = velocity
    for ox, oy in sorted(seen, key=lambda q: math.hypot(*q)):
        gap = math.hypot(ox, oy)
        if gap >= clearance:
            ux, uy = ox / gap, oy / gap
            towards = vx * ux + vy * uy
            over = towards - CLOSING * (gap - clearance)
            if over > 0.0:
                pace = math.hypot(vx, vy)
                side = uy * vx - ux * vy  # > 0: the way goes to its right
                rx, ry = (uy, -ux) if side >= 0.0 else (-uy, ux)
                vx, vy = vx - over * ux, vy - over * uy
                slide = math.sqrt(max(pace * pace - (towards - over) ** 2, 0.0))
                along = vx * rx + vy * ry
                vx, vy = vx + (slide - along) * rx, vy + (slide - along) * ry
    return (vx, vy)


def _side(ux: float, uy: float, near: Near, velocity: Point) -> float:
    """Which way to slide past the obstacle in direction (ux, uy): 1 to its right, -1 to its left.
    Away from the other near obstacles; else the way the robot wants to go; else right, so two
    robots meeting head-on both keep right and pass."""
    rx, ry = uy, -ux
    crowd = sum((rx * ox + ry * oy) * close for ox, oy, close in near if (ox, oy) != (ux, uy))
    if abs(crowd) > 1e-6:
        return -1.0 if crowd > 0 else 1.0
    want = rx * velocity[0] + ry * velocity[1]
    return -1.0 if want < -1e-6 * (1 + abs(velocity[0]) + abs(velocity[1])) else 1.0


def _away_from(near: Near, vx: float, vy: float) -> Point:
    """(vx, vy) with no part towards any of the `near` directions; (0, 0) when that cannot be had."""
    for _ in range(8):
        for ux, uy, _close in near:
            towards = vx * ux + vy * uy
            if towards > 0.0:
                vx, vy = vx - towards * ux, vy - towards * uy
    if any(vx * ux + vy * uy > 1e-6 for ux, uy, _close in near):
        return (0.0, 0.0)
    return (vx, vy)


def sensed(robot: Any, look: float, yaw: float) -> list[Point]:
    """What the robot senses within `look` metres, turned into the room frame by odometry's yaw: the
    proximity sensor's nearest points (light bodies), else the things its range finder sees
    (`things`: robots and a lifted table's legs, not walls; humanoids)."""
    if look <= 0.0:
        return []
    nearby = getattr(robot, "nearby", None)
    if nearby is not None:
        near = nearby(look)
    elif hasattr(robot, "scan"):
        near = things(robot.scan(BEAMS, look + 0.1), look)
    else:
        raise ValueError("`look` needs a body with a proximity sensor or a range finder")
    c, s = math.cos(yaw), math.sin(yaw)
    return [(c * f - s * left, s * f + c * left) for f, left in near]


@dataclass
class Sensing:
    """What a robot senses within `look` metres as it moves (`seen`, room frame, relative to it): a
    proximity sensor read every tick; a range finder's scan (ray casts, the dearer) every SCAN_EVERY
    seconds, the things it saw kept where they were in the odometry frame between scans."""

    robot: Any
    look: float
    _at: float = -math.inf
    _kept: list[Point] = field(default_factory=list)

    def seen(self, now: float, here: tuple[float, float, float]) -> list[Point]:
        if self.look <= 0.0:
            return []
        if getattr(self.robot, "nearby", None) is not None:
            return sensed(self.robot, self.look, here[2])
        if now - self._at >= SCAN_EVERY - 1e-9:
            self._at = now
            self._kept = [(here[0] + x, here[1] + y) for x, y in sensed(self.robot, self.look, here[2])]
        return [(x - here[0], y - here[1]) for x, y in self._kept]
