"""Perception parameters: every threshold in one frozen dataclass.

Colours are RGB triples in 0..1 as in hfsm_sim/profile.py; they are parameters, so the
behaviours (or a test) can pass other colours without touching the functions.
"""

from __future__ import annotations

from dataclasses import dataclass

from hfsm_sim.profile import FLOOR_COLOUR, ROBOT_COLOURS, TABLE_COLOUR, WALL_COLOUR

RGB = tuple[float, float, float]


@dataclass(frozen=True)
class PerceptionConfig:
    """Thresholds and priors. Pixel sizes are given as fractions of the image width or
    height where they must scale with resolution, so 160x120 and 640x480 agree."""

    # colours (hfsm_sim/profile.py)
    table_colour: RGB = TABLE_COLOUR
    robot_colours: tuple[RGB, ...] = ROBOT_COLOURS
    floor_colour: RGB = FLOOR_COLOUR
    wall_colour: RGB = WALL_COLOUR
    # colour classification (HSV, OpenCV scale: hue 0..180, s and v 0..255)
    hue_tolerance: int = 12           # +- hue units around a reference colour's hue
    min_saturation: int = 150         # table and robots are saturated; the floor is ~110
    min_value: int = 40               # shaded faces are darker but never near black
    wall_max_saturation: int = 60     # off-white walls render with s ~ 17
    wall_min_value: int = 100
    floor_saturation: tuple[int, int] = (60, 150)
    # blobs
    min_blob_fraction: float = 0.0005  # components smaller than this share of the image are noise
    open_kernel: int = 0               # morphological opening (px) before labelling; 0 = off
    # Figure 5 / paper section 5 margins
    centre_margin: float = 0.20        # corner inside cx +- margin*width/2  (256..384 of 640)
    near_row_fraction: float = 0.80    # "lowest pixel more than 80% to the bottom"
    # geometry priors (what the robots know of the table they move)
    table_top_height: float = 0.33     # top surface above the floor (m)
    table_edge_height: float = 0.30    # underside of the top: the lower edge of its rim (m)
    # edges and tables
    min_edge_px_fraction: float = 0.04  # fewest columns (of image width) for a near-edge fit
    wall_min_run: int = 2              # wall pixels needed directly above a floor-wall boundary
    table_gap: float = 0.15            # top-face pieces nearer than this (m) are one table...
    table_max_size: tuple[float, float] = (1.2, 0.8)  # ...if together no longer/wider (m)
    extent_gap: float = 0.3            # along a near edge, pixels past a gap this wide (m): another table


DEFAULT_CONFIG = PerceptionConfig()

