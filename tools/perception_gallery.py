"""What the robots see: render a few forward and down views, annotate what sim.perception
finds, write PNGs to docs/perception/, and (with --time) time each perception call.

Usage: .venv/bin/python tools/perception_gallery.py [--size 320x240] [--out docs/perception]
       [--time]
Colours in the pictures: yellow box = table blob, red dot = lowest pixel, magenta = the V
(corner and its two edges), cyan lines = Figure 5 centre band and the 80 % row, green =
floor-wall edge, white = table top outline, orange box = other robot, red line = down edge.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import cv2
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from sim.camera import CameraModel  # noqa: E402
from sim.perception import (  # noqa: E402
    DEFAULT_CONFIG,
    Blob,
    down_view,
    find_corner,
    find_robots,
    floor_wall_edge,
    table_distance,
    table_top_outline,
    wall_meet,
)
from sim.scenario import scenario_from_dict  # noqa: E402
from sim.world import World  # noqa: E402

Colour = tuple[int, int, int]
# name: (room, table, robots, head yaw/pitch in degrees, camera)
VIEWS: dict[str, tuple[dict[str, float], dict[str, float], dict[str, dict[str, float]],
                       tuple[float, float], str]] = {
    "far_2m": ({"width": 5, "depth": 5}, {}, {"r1": {"x": -1.81, "y": -1.66, "yaw": 50},
                                              "r2": {"x": 1.3, "y": 1.0, "yaw": -140}}, (0, 0), "forward"),
    "corner_0.8m": ({"width": 5, "depth": 5}, {}, {"r1": {"x": -0.97, "y": -0.82, "yaw": 45}},
                    (0, 15), "forward"),
    "look_left_at_corner": ({"width": 5, "depth": 5}, {}, {"r1": {"x": -0.97, "y": -0.82, "yaw": 45}},
                            (35, 15), "forward"),
    "wall_over_table": ({"width": 6, "depth": 6}, {"x": 2.25, "y": 0.0, "yaw": 90},
                        {"r1": {"x": 0.5, "y": 0.05, "yaw": 0}}, (0, 0), "forward"),
    "assistant_sees_leader": ({"width": 5, "depth": 5}, {},
                              {"r1": {"x": -1.6, "y": 0.1, "yaw": 0},
                               "r2": {"x": 0.65, "y": 0.0, "yaw": 180}},
                              (0, 5), "forward"),
    "down_at_grip": ({"width": 4, "depth": 4}, {}, {"r1": {"x": 0.1, "y": -0.38, "yaw": 98}}, (0, 0), "down"),
}


def render(name: str, size: tuple[int, int]) -> tuple[np.ndarray, CameraModel]:
    room, table, robots, (hy, hp), camera = VIEWS[name]
    scenario = scenario_from_dict({"room": room, "table": table, "robots": robots})
    with World(scenario, 0, image_size=size) as world:
        robot = world.robots["r1"]
        robot.set_head(math.radians(hy), math.radians(hp))
        world.advance(1.0)
        return robot.image(camera), robot.camera_model(camera)


def _pt(p: tuple[float, float]) -> tuple[int, int]:
    return (round(p[0]), round(p[1]))


def _box(img: np.ndarray, blob: Blob, colour: Colour) -> None:
    if blob.found:
        cv2.rectangle(img, (blob.left, blob.top), (blob.right, blob.lowest_row), colour, 1)


def _guides(out: np.ndarray, image: np.ndarray) -> None:
    """Figure 5 band and 80 % row, table top outline, floor-wall edge."""
    h, w = out.shape[:2]
    half = DEFAULT_CONFIG.centre_margin * w / 2
    for u in (w / 2 - half, w / 2 + half):
        cv2.line(out, (round(u), 0), (round(u), h - 1), (255, 255, 0), 1)
    row = round(DEFAULT_CONFIG.near_row_fraction * h)
    cv2.line(out, (0, row), (w - 1, row), (255, 255, 0), 1)
    us, tops = table_top_outline(image)
    out[tops.astype(int), us.astype(int)] = (255, 255, 255)
    fw = floor_wall_edge(image)
    if fw.found:
        seen = ~np.isnan(fw.rows)
        out[np.minimum(h - 1, fw.rows[seen].astype(int)), np.nonzero(seen)[0]] = (0, 255, 0)


def annotate_forward(image: np.ndarray, cam: CameraModel) -> np.ndarray:
    out = image[:, :, ::-1].copy()
    _guides(out, image)
    blob, ground = table_distance(image, cam)
    _box(out, blob, (0, 255, 255))
    for other in find_robots(image):
        _box(out, other, (0, 128, 255))
    text = []
    if ground.found:
        cv2.circle(out, _pt(ground.pixel), 3, (0, 0, 255), -1)
        text.append(f"table {ground.distance:.2f} m {math.degrees(ground.bearing):+.0f} deg"
                    + (" (clipped)" if ground.clipped else ""))
    c = find_corner(image, cam)
    for e in (c.left, c.right):
        if e.found:
            cv2.line(out, _pt(e.start), _pt(e.end), (255, 0, 255), 2)
    if c.found:
        text.append(f"V={c.is_v} L {c.left.length_m:.2f} R {c.right.length_m:.2f} m")
    m = wall_meet(image, cam)
    if m.found:
        text.append(f"wall gap {m.gap_px:.0f} px {m.gap_m:.2f} m meets={m.meets}")
    for i, t in enumerate(text):
        cv2.putText(out, t, (3, 12 + 12 * i), cv2.FONT_HERSHEY_PLAIN, 0.8, (255, 255, 255), 1)
    return out


def annotate_down(image: np.ndarray, cam: CameraModel) -> np.ndarray:
    out = image[:, :, ::-1].copy()
    w = out.shape[1]
    d = down_view(image, cam)
    if d.edge_found:
        slope = -math.tan(math.radians(d.image_angle_deg))
        p0 = (0, round(d.edge_v - slope * w / 2))
        p1 = (w - 1, round(d.edge_v + slope * (w / 2 - 1)))
        cv2.line(out, p0, p1, (0, 0, 255), 2)
    cv2.putText(out, f"blue {d.blue_fraction:.2f} edge {d.angle_deg:+.1f} deg {d.distance:.3f} m",
                (3, 12), cv2.FONT_HERSHEY_PLAIN, 0.8, (255, 255, 255), 1)
    return out


def gallery(size: tuple[int, int], out_dir: Path) -> list[Path]:
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, spec in VIEWS.items():
        image, cam = render(name, size)
        picture = annotate_down(image, cam) if spec[4] == "down" else annotate_forward(image, cam)
        path = out_dir / f"{name}.png"
        cv2.imwrite(str(path), picture, [cv2.IMWRITE_PNG_COMPRESSION, 9])
        paths.append(path)
    return paths


def _ms(fn: Callable[[], Any], repeat: int = 30) -> float:
    """Best of `repeat` runs (ms): the machine may be shared, the minimum is the cost."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return 1000 * min(times)


def _time_size(size: tuple[int, int]) -> dict[str, float]:
    fwd, cam = render("corner_0.8m", size)
    wall, wcam = render("wall_over_table", size)
    down, dcam = render("down_at_grip", size)
    return {"table_distance": _ms(lambda: table_distance(fwd, cam)),
            "find_robots (5 colours)": _ms(lambda: find_robots(fwd)),
            "find_corner": _ms(lambda: find_corner(fwd, cam)),
            "floor_wall_edge": _ms(lambda: floor_wall_edge(wall)),
            "wall_meet": _ms(lambda: wall_meet(wall, wcam)),
            "down_view": _ms(lambda: down_view(down, dcam))}


def timings() -> None:
    for size in ((160, 120), (640, 480)):
        rows = _time_size(size)
        print(f"{size[0]}x{size[1]}: " + ", ".join(f"{k} {v:.2f} ms" for k, v in rows.items()))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="320x240")
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "perception")
    parser.add_argument("--time", action="store_true", help="also time each call")
    args = parser.parse_args()
    w, h = (int(x) for x in args.size.split("x"))
    for path in gallery((w, h), args.out):
        print(path)
    if args.time:
        timings()


if __name__ == "__main__":
    main()
