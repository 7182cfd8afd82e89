"""Benchmark the sim package: physics steps/s, ms per image and the real-time factor of a scripted
run and of a trial, the robots' cameras drawn by the rasteriser and by pybullet's tiny renderer.

Usage: .venv/bin/python tools/bench_sim.py [--seconds 60] [--image-hz 2] [--rounds 3] [--no-doc]
Rewrites the bench_sim section of docs/PERFORMANCE.md; the last line printed is
`real-time factor: N` (the scripted run at 160x120, rasteriser, median of the rounds).
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

from hfsm.cli.quiet import stdout_to_stderr  # noqa: E402
from hfsm_behaviours.trial import TrialSpec, run_trial  # noqa: E402
from hfsm_sim.scenario import load_scenario  # noqa: E402
from hfsm_sim.world import World  # noqa: E402

TICK = 0.05
RENDERERS = ("raster", "tiny")
SIZES = ((160, 120), (640, 480))
TRIAL = ("opposite_long_side", 3)


def physics_steps_per_second(seconds: float) -> float:
    with World(load_scenario(), 0) as world:
        for robot in world.robots.values():
            robot.set_velocity(0.08, 0.02, 0.2)
        begin = time.perf_counter()
        world.advance(seconds)
        return seconds * world.physics_hz / (time.perf_counter() - begin)


def ms_per_image(size: tuple[int, int], renderer: str, repeats: int) -> dict[str, float]:
    result = {}
    with World(load_scenario(), 0, image_size=size, renderer=renderer) as world:
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


def scripted_rtf(seconds: float, image_hz: float, size: tuple[int, int] = (160, 120),
                 renderer: str = "raster") -> tuple[float, int, float]:
    """Two robots, 20 Hz control tick, each robot renders one camera at `image_hz`: the real-time
    factor by the wall clock, the images drawn, and the real-time factor by this process's CPU
    time (steadier when other work shares the cores)."""
    every = max(1, round(1.0 / (image_hz * TICK)))
    images = 0
    with World(load_scenario(), 0, image_size=size, renderer=renderer) as world:
        begin, cpu = time.perf_counter(), time.process_time()
        for tick in range(round(seconds / TICK)):
            _script(world, tick)
            world.advance(TICK)
            if tick % every == 0:
                for robot in world.robots.values():
                    robot.image("forward" if (tick // every) % 2 == 0 else "down")
                    images += 1
        wall, cpu = time.perf_counter() - begin, time.process_time() - cpu
        return seconds / wall, images, seconds / cpu


def trial(size: tuple[int, int], renderer: str) -> tuple[float, float]:
    """The paper's task on TRIAL's scenario and seed: (simulated s, wall s of the whole trial)."""
    spec = TrialSpec(str(ROOT / "machines" / "move_furniture.yaml"), *TRIAL, image_size=size,
                     renderer=renderer)
    with stdout_to_stderr():
        result = run_trial(spec)
    return result.time, result.wall


def _size(size: tuple[int, int]) -> str:
    return f"{size[0]}x{size[1]}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated s of the run")
    parser.add_argument("--image-hz", type=float, default=2.0, help="images per robot per s")
    parser.add_argument("--rounds", type=int, default=3, help="rounds of every run (medians)")
    parser.add_argument("--no-doc", action="store_true", help="do not touch PERFORMANCE.md")
    args = parser.parse_args()
    began = time.perf_counter()
    steps = physics_steps_per_second(20.0)
    keys = [(size, renderer) for size in SIZES for renderer in RENDERERS]
    images: dict[tuple[tuple[int, int], str], list[dict[str, float]]] = {k: [] for k in keys}
    rtf: dict[tuple[tuple[int, int], str], list[float]] = {k: [] for k in keys}
    rtf_cpu: dict[tuple[tuple[int, int], str], list[float]] = {k: [] for k in keys}
    walls: dict[tuple[tuple[int, int], str], list[float]] = {k: [] for k in keys}
    simulated = 0.0
    for round_ in range(args.rounds):
        for size, renderer in keys[round_ % 2:] + keys[:round_ % 2]:  # peers alternate first
            images[size, renderer].append(ms_per_image(size, renderer, 15 if size[0] < 320 else 5))
            wall_rtf, _, cpu_rtf = scripted_rtf(args.seconds, args.image_hz, size, renderer)
            rtf[size, renderer].append(wall_rtf)
            rtf_cpu[size, renderer].append(cpu_rtf)
            simulated, wall = trial(size, renderer)
            walls[size, renderer].append(wall)

    def med(values: list[float]) -> float:
        return statistics.median(values)

    def ms(key: tuple[tuple[int, int], str], camera: str) -> float:
        return med([m[camera] for m in images[key]])

    n_images = round(args.seconds * args.image_hz) * 2
    lines = [f"Measured by `tools/bench_sim.py` on {platform.machine()}, {os.cpu_count()} CPUs, "
             f"Python {platform.python_version()}: medians of {args.rounds} rounds, the renderers "
             f"alternated ({time.perf_counter() - began:.0f} s in all).", "",
             f"- physics (2 robots walking, 120 Hz): {steps:,.0f} steps/s",
             f"- scripted run: two robots, {args.seconds:.0f} s simulated, 120 Hz physics, "
             f"{args.image_hz:g} images/s per robot ({n_images} images), forward and down in turn",
             f"- trial: machines/move_furniture.yaml on {TRIAL[0]}, seed {TRIAL[1]} "
             f"({simulated:.0f} s simulated), the whole `run_trial` (load, check, world, run)", "",
             "| image | renderer | forward ms | down ms | scripted run: real-time factor "
             "| (by CPU time) | trial: wall s | trial: real-time factor |",
             "|---|---|---:|---:|---:|---:|---:|---:|"]
    for key in keys:
        lines.append(f"| {_size(key[0])} | {key[1]} | {ms(key, 'forward'):.1f} | "
                     f"{ms(key, 'down'):.1f} | {med(rtf[key]):.1f} | {med(rtf_cpu[key]):.1f} | "
                     f"{med(walls[key]):.2f} | {simulated / med(walls[key]):.1f} |")
    lines += ["", "Rasteriser against the tiny renderer (tiny / raster):", ""]
    for size in SIZES:
        new, old = (size, "raster"), (size, "tiny")
        lines.append(
            f"- {_size(size)}: images {ms(old, 'forward') / ms(new, 'forward'):.1f}x (forward), "
            f"{ms(old, 'down') / ms(new, 'down'):.1f}x (down); scripted run "
            f"{med(rtf[new]) / med(rtf[old]):.2f}x; trial {med(walls[old]) / med(walls[new]):.2f}x")
    headline = med(rtf[(160, 120), "raster"])
    lines += ["", f"- real-time factor of the scripted run at 160x120: **{headline:.1f}** "
              f"(by CPU time {med(rtf_cpu[(160, 120), 'raster']):.1f}; target >= 60); at 640x480: "
              f"**{med(rtf[(640, 480), 'raster']):.1f}** (by CPU time "
              f"{med(rtf_cpu[(640, 480), 'raster']):.1f}; target >= 15)"]
    print("\n".join(lines))
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_sim", lines)
    print(f"real-time factor: {headline:.1f}")


if __name__ == "__main__":
    main()
