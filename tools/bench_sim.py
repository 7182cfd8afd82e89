"""Benchmark the sim package: physics steps/s, ms per image, real-time factor of a scripted run.

Usage: .venv/bin/python tools/bench_sim.py [--seconds 60] [--image-hz 2] [--no-doc]
Rewrites the bench_sim section of docs/PERFORMANCE.md; the last line printed is
`real-time factor: N`.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
for folder in (ROOT, ROOT / "tools"):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))

from docsection import write_section  # noqa: E402

from sim.scenario import load_scenario  # noqa: E402
from sim.world import World  # noqa: E402

TICK = 0.05


def physics_steps_per_second(seconds: float) -> float:
    with World(load_scenario(), 0) as world:
        for robot in world.robots.values():
            robot.set_velocity(0.08, 0.02, 0.2)
        begin = time.perf_counter()
        world.advance(seconds)
        return seconds * world.physics_hz / (time.perf_counter() - begin)


def ms_per_image(width: int, repeats: int) -> dict[str, float]:
    result = {}
    with World(load_scenario(), 0, image_size=(width, width * 3 // 4)) as world:
        robot = world.robots["r1"]
        for camera in ("forward", "down"):
            robot.image(camera)
            times = []
            for _ in range(repeats):
                begin = time.perf_counter()
                robot.image(camera)
                times.append(time.perf_counter() - begin)
            result[camera] = 1000 * statistics.median(times)
    return result


def _script(world: World, tick: int) -> None:
    """Each robot cycles walk / turn / crab every 2 s, with head sweeps."""
    for index, robot in enumerate(world.robots.values()):
        phase = (tick // 40 + index) % 3
        robot.set_velocity(*((0.1, 0.0, 0.0), (0.0, 0.0, 0.5), (0.0, 0.05, 0.0))[phase])
        if tick % 20 == 0:
            robot.set_head(math.sin(tick / 40 + index), 0.2)


def scripted_rtf(seconds: float, image_hz: float) -> tuple[float, int]:
    """Two robots, 20 Hz control tick, each robot renders one camera at `image_hz`."""
    every = max(1, round(1.0 / (image_hz * TICK)))
    images = 0
    with World(load_scenario(), 0) as world:
        begin = time.perf_counter()
        for tick in range(round(seconds / TICK)):
            _script(world, tick)
            world.advance(TICK)
            if tick % every == 0:
                for robot in world.robots.values():
                    robot.image("forward" if (tick // every) % 2 == 0 else "down")
                    images += 1
        return seconds / (time.perf_counter() - begin), images


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated s of the run")
    parser.add_argument("--image-hz", type=float, default=2.0, help="images per robot per s")
    parser.add_argument("--no-doc", action="store_true", help="do not touch PERFORMANCE.md")
    args = parser.parse_args()
    steps = physics_steps_per_second(20.0)
    lines = [f"Measured by `tools/bench_sim.py` on {platform.machine()}, "
             f"{os.cpu_count()} CPUs, Python {platform.python_version()}.", "",
             f"- physics (2 robots walking, 120 Hz): {steps:,.0f} steps/s", "",
             "| image | forward ms | down ms |", "|---|---|---|"]
    for width, repeats in ((160, 40), (320, 15), (640, 6)):
        ms = ms_per_image(width, repeats)
        lines.append(f"| {width}x{width * 3 // 4} | {ms['forward']:.1f} | {ms['down']:.1f} |")
    rtf, images = scripted_rtf(args.seconds, args.image_hz)
    lines += ["", f"- scripted two-robot run: {args.seconds:.0f} s simulated, 160x120, "
              f"{args.image_hz:g} images/s per robot ({images} images), 120 Hz physics: "
              f"**real-time factor {rtf:.1f}**"]
    print("\n".join(lines))
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_sim", lines)
    print(f"real-time factor: {rtf:.1f}")


if __name__ == "__main__":
    main()
