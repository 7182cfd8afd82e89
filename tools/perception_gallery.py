"""What the robots see: render a few forward and down views, annotate what hfsm_sim.perception
finds, write PNGs to docs/perception/, and (with --time) time each perception call.

Usage: .venv/bin/python tools/perception_gallery.py [--size 320x240] [--out docs/perception]
       [--time]
Colours in the pictures: yellow box = table blob, red dot = lowest pixel, cyan lines = Figure 5
centre band and the 80 % row, magenta = each table top's rectangle (from the floor plan back into
the image; the text gives it in the odometry frame), green = floor-wall line, orange box = other
robot, red line = the near edge (down).
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

from hfsm_sim.perception import (  # noqa: E402
    DEFAULT_CONFIG,
    Blob,
    CameraModel,
    find_robots,
    floor_wall_line,
    near_edge,
    see_tables,
    table_distance,
    table_rect,
    wall_to_side,
)
from hfsm_sim.robot import Robot  # noqa: E402
from hfsm_sim.scenario import scenario_from_dict  # noqa: E402
from hfsm_sim.world import World  # noqa: E402

Colour = tuple[int, int, int]
Tables = list[dict[str, float]]
# name: (room, tables, robots, head yaw/pitch in degrees, camera)
VIEWS: dict[str, tuple[dict[str, float], Tables, dict[str, dict[str, float]],
                       tuple[float, float], str]] = {
    "far_2m": ({"width": 5, "depth": 5}, [{}], {"r1": {"x": -1.81, "y": -1.66, "yaw": 50},
                                              "r2": {"x": 1.3, "y": 1.0, "yaw": -140}}, (0, 0), "forward"),
    "corner_0.8m": ({"width": 5, "depth": 5}, [{}], {"r1": {"x": -0.97, "y": -0.82, "yaw": 45}},
                    (0, 15), "forward"),
    "look_left_at_corner": ({"width": 5, "depth": 5}, [{}], {"r1": {"x": -0.97, "y": -0.82, "yaw": 45}},
                            (35, 15), "forward"),
    "wall_over_table": ({"width": 6, "depth": 6}, [{"x": 2.25, "y": 0.0, "yaw": 90}],
                        {"r1": {"x": 0.5, "y": 0.05, "yaw": 0}}, (0, 0), "forward"),
    "assistant_sees_leader": ({"width": 5, "depth": 5}, [{}],
                              {"r1": {"x": -1.6, "y": 0.1, "yaw": 0},
                               "r2": {"x": 0.65, "y": 0.0, "yaw": 180}},
                              (0, 5), "forward"),
    "down_at_grip": ({"width": 4, "depth": 4}, [{}], {"r1": {"x": 0.1, "y": -0.38, "yaw": 98}},
                     (0, 0), "down"),
    "three_tables": ({"width": 8, "depth": 8},
                     [{"x": 0.0, "y": 0.0}, {"x": -1.3, "y": -0.5, "yaw": 60, "length": 1.0},
                      {"x": 1.4, "y": -0.6, "yaw": 100, "width": 0.6}],
                     {"r1": {"x": 0.0, "y": -1.4, "yaw": 90}, "r2": {"x": 0.0, "y": -0.5, "yaw": -90}},
                     (22, 14), "forward"),
}


def render(name: str, size: tuple[int, int]) -> tuple[np.ndarray, CameraModel]:
    room, tables, robots, (hy, hp), camera = VIEWS[name]
    scenario = scenario_from_dict({"room": room, "tables": tables, "robots": robots})
    with World(scenario, 0, image_size=size) as world:
        robot = world.robots["r1"]
        assert isinstance(robot, Robot)
        robot.set_head(math.radians(hy), math.radians(hp))
        world.advance(1.0)
        return robot.image(camera), robot.camera_model(camera)


def _pt(p: tuple[float, float]) -> tuple[int, int]:
    return (round(p[0]), round(p[1]))


def _box(img: np.ndarray, blob: Blob, colour: Colour) -> None:
    if blob.found:
        cv2.rectangle(img, (blob.left, blob.top), (blob.right, blob.lowest_row), colour, 1)


def _guides(out: np.ndarray, image: np.ndarray) -> None:
    """Figure 5 band and 80 % row, floor-wall line."""
    h, w = out.shape[:2]
    half = DEFAULT_CONFIG.centre_margin * w / 2
    for u in (w / 2 - half, w / 2 + half):
        cv2.line(out, (round(u), 0), (round(u), h - 1), (255, 255, 0), 1)
    row = round(DEFAULT_CONFIG.near_row_fraction * h)
    cv2.line(out, (0, row), (w - 1, row), (255, 255, 0), 1)
    us, vs = floor_wall_line(image)
    out[np.minimum(h - 1, vs.astype(int)), us.astype(int)] = (0, 255, 0)


def _polyline(out: np.ndarray, cam: CameraModel, points: list[tuple[float, float]], z: float,
              colour: Colour, closed: bool) -> None:
    """Body-frame floor-plan points at height z, drawn where the camera sees them."""
    pixels = [cam.project((x, y, z)) for x, y in points]
    if all(p is not None for p in pixels):
        poly = np.array([_pt(p) for p in pixels if p is not None], np.int32)
        cv2.polylines(out, [poly], closed, colour, 1)


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
    for seen in see_tables([(image, cam)]):
        rect = seen.rect
        corners = [(float(x), float(y)) for x, y in cam.to_body(np.array(rect.corners()))]
        _polyline(out, cam, corners, DEFAULT_CONFIG.table_top_height, (255, 0, 255), True)
        text.append(f"table {rect.length:.2f} x {rect.width:.2f} m at ({rect.x:.2f}, {rect.y:.2f})"
                    f" {math.degrees(rect.axis):+.0f} deg" + (" (clipped)" if seen.clipped else ""))
    for side in ("left", "right"):
        wall = wall_to_side(image, cam, side)
        if wall.found:
            text.append(f"wall {side} {wall.distance:.2f} m")
    for i, t in enumerate(text):
        cv2.putText(out, t, (3, 12 + 12 * i), cv2.FONT_HERSHEY_PLAIN, 0.8, (255, 255, 255), 1)
    return out


def annotate_down(image: np.ndarray, cam: CameraModel) -> np.ndarray:
    out = image[:, :, ::-1].copy()
    edge = near_edge(image, cam)
    text = "no near edge"
    if edge.found:
        c, s = math.cos(edge.turn), math.sin(edge.turn)
        centre = (edge.distance * c, edge.distance * s)
        ends = [(centre[0] - k * s, centre[1] + k * c) for k in (-0.5, 0.5)]
        _polyline(out, cam, ends, DEFAULT_CONFIG.table_edge_height, (0, 0, 255), False)
        text = f"near edge {edge.distance:.3f} m, turn {math.degrees(edge.turn):+.1f} deg"
    cv2.putText(out, text, (3, 12), cv2.FONT_HERSHEY_PLAIN, 0.8, (255, 255, 255), 1)
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
            "table_rect": _ms(lambda: table_rect(fwd, cam)),
            "see_tables": _ms(lambda: see_tables([(fwd, cam)])),
            "floor_wall_line": _ms(lambda: floor_wall_line(wall)),
            "wall_to_side": _ms(lambda: wall_to_side(wall, wcam, "left")),
            "near_edge": _ms(lambda: near_edge(down, dcam))}


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
