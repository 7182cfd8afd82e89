"""The safety layer under every motion of a humanoid: no plan can drive it into another robot.

`Guarded` stands between the behaviours and the body (the world hands it to primitives as their
robot, as `Localised` is for light robots): every velocity a primitive commands (a walk, an
approach, a step of a carry, a turn, a step back) is scaled each tick by what the range finder
sees in the way (`let_through`): full speed while nothing is within SLOW metres ahead along the
motion, slowing to a stop at STOP metres, and moving again when the way clears. What stands
beside or behind the way never slows it, so a robot can always move off. While the hands hold a
table, what lies in front (the table's own legs, the partner across it) is left out; a carrying
pair stops together because every part of a step ends at a barrier (machines/step_together.yaml):
the robot held back finishes its part later (`Body` counts only the time it was let move), and its
partner waits at the barrier.

Nothing here reads the simulator's truth: the ranges (`things`), and odometry to keep what was seen
between scans where it was.
"""

from __future__ import annotations

import math
from typing import Any

from hfsm_behaviours.drive.things import BEAMS, things

Point = tuple[float, float]
STOP, SLOW = 0.30, 0.55  # metres from the body's centre to a thing ahead: stopped, slowing below
LANE = 0.30  # metres either side of the line of motion a thing must lie within to be in the way
TURN_STOP = 0.22  # a turn on the spot stops for a thing this near (its corners sweep)
LOOK = SLOW + 0.2  # metres within which things count
READ = 2.5  # metres the range finder is read to: walls seen long enough to be told from things
SCAN_EVERY = 0.25  # seconds between the guard's scans (a NAO's sonars read at ~10 Hz)
HOLDING_FRONT = 0.0  # while holding a table: things farther forward than this are the table's


def let_through(velocity: tuple[float, float, float], seen: list[Point], holding: bool) -> float:
    """The fraction (0-1) of `velocity` (forward, left, turn; body frame) to let through, given the
    things `seen` (forward, left; body frame)."""
    forward, left, turn = velocity
    pace = math.hypot(forward, left)
    if holding:
        seen = [p for p in seen if p[0] <= HOLDING_FRONT]
    if pace < 1e-9:
        if turn != 0.0 and any(math.hypot(*p) < TURN_STOP for p in seen):
            return 0.0
        return 1.0
    ux, uy = forward / pace, left / pace
    fraction = 1.0
    for px, py in seen:
        along = px * ux + py * uy
        if along <= 0.0 or abs(px * uy - py * ux) > LANE:
            continue
        fraction = min(fraction, max(0.0, min(1.0, (along - STOP) / (SLOW - STOP))))
    return fraction


class Guarded:
    """A humanoid as the behaviours drive it: everything is the body's, except that the velocity it
    is commanded (`set_velocity`, `stop`) goes to the body scaled by `let_through`, re-judged every
    tick by the world (`update`). `passed` is the fraction let through in the last tick and `held`
    the seconds its wanted motion has been stopped outright."""

    body_kind = "full"

    def __init__(self, robot: Any) -> None:
        self.body = robot
        self.guard = self
        self.passed = 1.0
        self.held = 0.0
        self._want = (0.0, 0.0, 0.0)
        self._scale = 1.0
        self._at = -math.inf
        self._kept: list[Point] = []  # things last seen, in the odometry frame

    def __getattr__(self, name: str) -> Any:
        return getattr(self.body, name)

    def set_velocity(self, forward: float, sideways: float, turn: float) -> None:
        self._want = (forward, sideways, turn)
        self._apply()

    def stop(self) -> None:
        self.set_velocity(0.0, 0.0, 0.0)

    def velocity(self) -> tuple[float, float, float]:
        return tuple(self.body.velocity())

    def update(self, now: float, dt: float) -> None:
        """Judge the wanted motion against what is in the way, before the world's next step."""
        moving = any(v != 0.0 for v in self._want)
        if not moving or self.body.failed:
            self._scale, self.passed, self.held = 1.0, 1.0, 0.0
            return
        here = self.body.odometry()
        c, s = math.cos(here[2]), math.sin(here[2])
        if now - self._at >= SCAN_EVERY - 1e-9:
            self._at = now
            near = [q for q in things(self.body.scan(BEAMS, READ), READ) if math.hypot(*q) < LOOK]
            self._kept = [(here[0] + c * f - s * lft, here[1] + s * f + c * lft) for f, lft in near]
        seen = [(c * (x - here[0]) + s * (y - here[1]), -s * (x - here[0]) + c * (y - here[1]))
                for x, y in self._kept]
        self._scale = let_through(self._want, seen, bool(self.body.holding()))
        translating = self._want[0] != 0.0 or self._want[1] != 0.0
        self.held = self.held + dt if self._scale == 0.0 and translating else 0.0
        self.passed = self._scale
        self._apply()

    def _apply(self) -> None:
        forward, left, turn = self._want
        scale = self._scale
        if scale >= 1.0:
            self.body.set_velocity(forward, left, turn)
        elif math.hypot(forward, left) > 1e-9:  # a turn with the walk goes on: it may turn it away
            self.body.set_velocity(forward * scale, left * scale, turn)
        else:
            self.body.set_velocity(0.0, 0.0, turn * scale)
