"""Benchmark the simulator at team scale: real-time factor with 2, 8 and 16 humanoids (cameras read
as primitives read them) and with 10, 25 and 50 light robots (no cameras).

Usage: .venv/bin/python tools/bench_team.py [--seconds 10] [--rounds 3] [--image-hz 2] [--no-doc]
Rewrites the bench_team section of docs/PERFORMANCE.md. Each figure is the median of `rounds`
runs of `seconds` simulated seconds at a 20 Hz control tick and 120 Hz physics.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parents[1]
for folder in (ROOT, ROOT / "tools"):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))

from docsection import write_section  # noqa: E402

from hfsm_sim.robot import Robot  # noqa: E402
from hfsm_sim.scenario import Scenario, load_scenario, resolve, scenario_from_dict  # noqa: E402
from hfsm_sim.world import World  # noqa: E402

TICK = 0.05
FULL = {2: "opposite_long_side", 8: "team_8", 16: "team_16"}
LIGHT = (10, 25, 50)
WALKS = ((0.1, 0.0, 0.0), (0.0, 0.0, 0.5), (0.0, 0.05, 0.0))
SHUTTLE = """
outcomes: [late]
states:
  go: {do: go_to, with: {x: 0.0, y: 3.0, relative: true}, on: {arrived: back, timeout: late}}
  back: {do: go_to, with: {x: 0.0, y: -3.0, relative: true}, on: {arrived: go, timeout: late}}
"""


def light_team(n: int) -> Scenario:
    """The first n robots of alloc_50, in its room with its targets."""
    data: dict[str, Any] = yaml.safe_load(resolve("alloc_50").read_text(encoding="utf-8"))
    data["robots"] = dict(list(data["robots"].items())[:n])
    return scenario_from_dict(data)


def _walk(world: World, tick: int) -> None:
    """Humanoids cycle walk / turn / crab every 2 s; light robots drive to a target and back."""
    targets = world.scenario.targets
    for index, robot in enumerate(world.robots.values()):
        if isinstance(robot, Robot):
            robot.set_velocity(*WALKS[(tick // 40 + index) % 3])
            continue
        goal = targets[index % len(targets)] if (tick // 200) % 2 == 0 else None
        x, y, yaw = robot.odometry()
        home = world.scenario.robots[robot.name]
        gx, gy = (goal.x, goal.y) if goal else (home.x, home.y)
        heading = math.atan2(gy - y, gx - x) - yaw
        robot.set_velocity(math.hypot(gx - x, gy - y), 0.0, math.atan2(math.sin(heading), math.cos(heading)))


def rtf(scenario: Scenario, seconds: float, image_hz: float) -> tuple[float, int]:
    """Simulated over CPU seconds of a scripted run; each humanoid renders its forward
    camera `image_hz` times a second (0: never)."""
    every = max(1, round(1.0 / (image_hz * TICK))) if image_hz else 0
    images = 0
    with World(scenario, 0) as world:
        begin = time.process_time()
        for tick in range(round(seconds / TICK)):
            _walk(world, tick)
            world.advance(TICK)
            if every and tick % every == 0:
                for robot in world.robots.values():
                    if isinstance(robot, Robot):
                        robot.image("forward")
                        images += 1
        return seconds / (time.process_time() - begin), world.score()["robot_collisions"]


def ms_per_image(scenario: Scenario, repeats: int = 10) -> float:
    with World(scenario, 0) as world:
        robot = next(iter(world.robots.values()))
        assert isinstance(robot, Robot)
        robot.image("forward")
        times = []
        for _ in range(repeats):
            begin = time.process_time()
            robot.image("forward")
            times.append(time.process_time() - begin)
        return 1000 * statistics.median(times)


def whole_run_rtf(scenario: str, seconds: float) -> float:
    """Simulated over CPU seconds of `hfsm-run --world sim` (start-up included): every robot runs a
    machine that shuttles it 3 m forward and back with go_to, until --max-time."""
    with tempfile.TemporaryDirectory() as folder:
        machine = Path(folder) / "shuttle.yaml"
        machine.write_text(SHUTTLE, encoding="utf-8")
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run([sys.executable, "-m", "hfsm.cli.run", str(machine), "--world", "sim", "--scenario",
                        scenario, "--no-video", "--out", folder, "--quiet", "--max-time", f"{seconds:g}"],
                       check=False, capture_output=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return seconds / (after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)


def median_rtf(scenario: Scenario, seconds: float, image_hz: float, rounds: int) -> float:
    return statistics.median(rtf(scenario, seconds, image_hz)[0] for _ in range(rounds))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0, help="simulated s of each run")
    parser.add_argument("--rounds", type=int, default=3, help="runs per figure (the median is shown)")
    parser.add_argument("--image-hz", type=float, default=2.0, help="forward images per humanoid per s")
    parser.add_argument("--no-doc", action="store_true", help="do not touch PERFORMANCE.md")
    args = parser.parse_args()
    hz = args.image_hz
    command = f"tools/bench_team.py --seconds {args.seconds:g} --rounds {args.rounds} --image-hz {hz:g}"
    lines = [f"Measured by `{command}` on {platform.machine()}, {os.cpu_count()} CPUs, Python "
             f"{platform.python_version()}: the median real-time factor of {args.rounds} scripted runs of "
             f"{args.seconds:g} simulated s (20 Hz control, 120 Hz physics), as simulated seconds over the "
             "process's CPU seconds (one core's worth; the machine is shared, so wall-clock figures are "
             "lower by the load). Humanoids walk, turn and crab in turn; cameras are rendered only when "
             f"read, here each humanoid's forward camera {hz:g} times a second (160x120); light robots "
             "drive to a target and back.", "",
             f"| robots | scenario | ms per image | RTF, no images | RTF, {hz:g} images/s each |",
             "|---|---|---|---|---|"]
    for n, name in FULL.items():
        scenario = load_scenario(name)
        row = (f"| {n} full | `{name}` | {ms_per_image(scenario):.1f} | "
               f"{median_rtf(scenario, args.seconds, 0.0, args.rounds):.1f} | "
               f"**{median_rtf(scenario, args.seconds, hz, args.rounds):.1f}** |")
        print(row, flush=True)
        lines.append(row)
    for n in LIGHT:
        row = (f"| {n} light | `alloc_50`, first {n} | - | "
               f"**{median_rtf(light_team(n), args.seconds, 0.0, args.rounds):.1f}** | - |")
        print(row, flush=True)
        lines.append(row)
    lines += ["", "A whole `hfsm-run --world sim` (the engine, 20 Hz, every robot running a machine that "
              "shuttles it 3 m forward and back with `go_to`; start-up included; simulated over CPU seconds, "
              f"median of {args.rounds}):", ""]
    for name in ("alloc_3_tasks", "alloc_50"):
        seconds = 6 * args.seconds
        whole = statistics.median(whole_run_rtf(name, seconds) for _ in range(args.rounds))
        robots = len(load_scenario(name).robots)
        row = f"- `{name}` ({robots} light robots, {seconds:g} s simulated): **RTF {whole:.1f}**"
        print(row, flush=True)
        lines.append(row)
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_team", lines)


if __name__ == "__main__":
    main()
