"""Dead reckoning in the robot's own start frame (or from a start pose it was told), with seeded
scale errors and yaw drift."""

from __future__ import annotations

import math

import numpy as np


def wrap(angle: float) -> float:
    return (angle + math.pi) % (2 * math.pi) - math.pi


class Odometry:
    """Integrates the body's true motion, per update, with per-robot biases and noise:
    forward scale ~2 %, sideways ~4 %, turn ~2 % (1 sigma), yaw drift ~0.02 rad per metre."""

    def __init__(self, rng: np.random.Generator, start: tuple[float, float, float],
                 told: tuple[float, float, float] | None = None) -> None:
        self._rng = rng
        self._scale = 1.0 + rng.normal(0.0, [0.02, 0.04, 0.02])
        self._drift = float(rng.normal(0.0, 0.02))
        self._last = start
        self._pose = told or (0.0, 0.0, 0.0)

    def pose(self) -> tuple[float, float, float]:
        return self._pose

    def update(self, true_pose: tuple[float, float, float]) -> None:
        (x0, y0, a0), (x1, y1, a1) = self._last, true_pose
        self._last = true_pose
        c, s = math.cos(a0), math.sin(a0)
        fwd, side = c * (x1 - x0) + s * (y1 - y0), -s * (x1 - x0) + c * (y1 - y0)
        turn = wrap(a1 - a0)
        dist = math.hypot(fwd, side)
        if dist < 1e-6 and abs(turn) < 1e-6:
            return
        noise = self._rng.normal(0.0, 1.0, 3)
        fwd = fwd * self._scale[0] + noise[0] * 0.01 * dist
        side = side * self._scale[1] + noise[1] * 0.01 * dist
        turn = turn * self._scale[2] + self._drift * dist + noise[2] * (0.01 * abs(turn)
                                                                         + 0.002 * dist)
        ox, oy, oa = self._pose
        mid = oa + turn / 2
        cm, sm = math.cos(mid), math.sin(mid)
        self._pose = (ox + cm * fwd - sm * side, oy + sm * fwd + cm * side, wrap(oa + turn))
