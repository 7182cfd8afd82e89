"""Pixel classes by colour: the blue table and its lit top face, the robots, floor and walls.

Hue tells the classes apart (shading changes value, not hue); saturation and value keep the
off-white walls and the moderately saturated brown floor out of the saturated table and robots.
Every function returns a boolean H x W mask.
"""

from __future__ import annotations

import cv2
import numpy as np

from hfsm_sim.perception.config import DEFAULT_CONFIG, RGB, PerceptionConfig


def to_hsv(image: np.ndarray) -> np.ndarray:
    """RGB uint8 image to OpenCV HSV (hue 0..179)."""
    return np.asarray(cv2.cvtColor(image, cv2.COLOR_RGB2HSV))


def colour_hue(colour: RGB) -> int:
    """OpenCV hue (0..179) of an RGB colour given in 0..1."""
    pixel = np.array([[[round(255 * c) for c in colour]]], dtype=np.uint8)
    return int(to_hsv(pixel)[0, 0, 0])


def hue_lut(hue: int, tolerance: int) -> np.ndarray:
    """Boolean table over OpenCV hues 0..255: within `tolerance` of `hue` (circular, 180)."""
    diff = np.abs(np.arange(256) - hue)
    return np.asarray(np.minimum(diff, 180 - diff % 180) <= tolerance)


def hue_near(hsv: np.ndarray, colour: RGB, cfg: PerceptionConfig) -> np.ndarray:
    """Pixels whose hue is within `hue_tolerance` of the colour's."""
    return np.asarray(hue_lut(colour_hue(colour), cfg.hue_tolerance)[hsv[..., 0]])


def colour_mask(hsv: np.ndarray, colour: RGB, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Pixels of the colour's hue that are saturated and bright enough."""
    sv = cv2.inRange(hsv, (0, cfg.min_saturation, cfg.min_value), (255, 255, 255))
    return np.asarray(hue_near(hsv, colour, cfg) & (sv > 0))


def table_mask(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """The table's (blue) pixels: top, rim and legs."""
    return colour_mask(to_hsv(image), cfg.table_colour, cfg)


def top_face(image: np.ndarray, value_ratio: float = 0.9,
             cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """The tables' lit top faces: the light comes from above, so the top is the brightest blue
    face; blue pixels within `value_ratio` of the brightest blue value."""
    hsv = to_hsv(image)
    blue = colour_mask(hsv, cfg.table_colour, cfg)
    if not blue.any():
        return blue
    value = hsv[..., 2]
    return np.asarray(blue & (value >= value_ratio * float(value[blue].max())))


def floor_mask(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Floor pixels: the floor's hue at the floor's moderate saturation."""
    hsv = to_hsv(image)
    low, high = cfg.floor_saturation
    return np.asarray(hue_near(hsv, cfg.floor_colour, cfg) & (hsv[..., 1] >= low)
                      & (hsv[..., 1] <= high))


def wall_mask(image: np.ndarray, cfg: PerceptionConfig = DEFAULT_CONFIG) -> np.ndarray:
    """Off-white wall pixels: low saturation, bright."""
    hsv = to_hsv(image)
    return np.asarray((hsv[..., 1] <= cfg.wall_max_saturation) & (hsv[..., 2] >= cfg.wall_min_value))
