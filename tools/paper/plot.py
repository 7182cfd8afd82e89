"""Figure 11 as a PNG: failure rate against the maximum time allowed (drawn with OpenCV)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import cv2
import numpy as np

W, H, LEFT, RIGHT, TOP, BOTTOM = 640, 420, 70, 20, 55, 50
FONT = cv2.FONT_HERSHEY_SIMPLEX


def _xy(minutes: float, rate: float, max_minutes: float) -> tuple[int, int]:
    x = LEFT + (W - LEFT - RIGHT) * minutes / max_minutes
    y = H - BOTTOM - (H - TOP - BOTTOM) * rate
    return round(x), round(y)


def failure_plot(curves: dict[str, Sequence[tuple[float, float]]], path: Path, title: str) -> None:
    """Each curve: (limit in seconds, failure rate) points; one line per curve, in grey levels."""
    image = np.full((H, W, 3), 255, np.uint8)
    max_minutes = max(limit for points in curves.values() for limit, _ in points) / 60
    _axes(image, max_minutes)
    shades = [(0, 0, 0), (0, 0, 200), (160, 60, 0), (0, 140, 0)]
    for i, (name, points) in reversed(list(enumerate(curves.items()))):  # the first curve on top
        pixels = [_xy(limit / 60, rate, max_minutes) for limit, rate in points]
        width = 3 if i == 0 else 2
        cv2.polylines(image, [np.array(pixels, np.int32)], False, shades[i % len(shades)], width, cv2.LINE_AA)
        shade = shades[i % len(shades)]
        cv2.putText(image, name, (W - 230, TOP + 20 + 18 * i), FONT, 0.45, shade, 1, cv2.LINE_AA)
    cv2.putText(image, title, (LEFT, 22), FONT, 0.5, (0, 0, 0), 1, cv2.LINE_AA)
    path.parent.mkdir(parents=True, exist_ok=True)
    cv2.imwrite(str(path), image)


def _axes(image: np.ndarray, max_minutes: float) -> None:
    black = (0, 0, 0)
    cv2.line(image, (LEFT, H - BOTTOM), (W - RIGHT, H - BOTTOM), black, 1)
    cv2.line(image, (LEFT, TOP), (LEFT, H - BOTTOM), black, 1)
    step = 5 if max_minutes > 20 else 1 if max_minutes > 4 else 0.5
    for i in range(int(max_minutes / step) + 1):
        minute = i * step
        x, y = _xy(minute, 0, max_minutes)
        cv2.line(image, (x, y), (x, y + 5), black, 1)
        cv2.putText(image, f"{minute:g}", (x - 8, y + 20), FONT, 0.4, black, 1, cv2.LINE_AA)
    for tenth in range(0, 11, 2):
        x, y = _xy(0, tenth / 10, max_minutes)
        cv2.line(image, (x - 5, y), (x, y), black, 1)
        cv2.putText(image, f"{tenth * 10}%", (x - 45, y + 5), FONT, 0.4, black, 1, cv2.LINE_AA)
    label = "maximum time allowed (minutes)"
    cv2.putText(image, label, (W // 2 - 120, H - 12), FONT, 0.45, black, 1, cv2.LINE_AA)
    cv2.putText(image, "failure rate", (5, TOP - 12), FONT, 0.45, black, 1, cv2.LINE_AA)
