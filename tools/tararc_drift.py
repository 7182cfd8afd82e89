"""How far the light robots of one TARARC bench trial are from where they believe they are.

    nice -n 10 .venv/bin/python tools/tararc_drift.py --robots 50 --seed 2

Runs Figure 6's trial (`tools/tararc/scenes.py`, `--robots` robots, 3 targets for every 10) with
machines/tararc.yaml, as the bench does, then reads the simulator's truth (a measurement, never
given to the robots) and prints, at the end of the run, each robot's error of position: of the
pose the behaviours drive by (odometry corrected by the laser against the room,
hfsm_behaviours/drive/localise.py) and of its raw odometry alone.
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import tempfile
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hfsm.load import load  # noqa: E402
from hfsm.registry import Registry  # noqa: E402
from hfsm.runtime.program import Program, machine_params  # noqa: E402
from hfsm.runtime.run import RunOptions, run  # noqa: E402
from hfsm_behaviours.simworld import SimWorld, load_scenario  # noqa: E402
from hfsm_sim import World  # noqa: E402
from tools.tararc.measure import Timeline, measure  # noqa: E402
from tools.tararc.scenes import scene  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robots", type=int, default=50)
    parser.add_argument("--seed", type=int, default=2)
    parser.add_argument("--max-time", type=float, default=300.0)
    args = parser.parse_args()
    data = scene(robots=args.robots, tasks=3 * args.robots // 10)
    with tempfile.TemporaryDirectory(prefix="tararc-drift-") as tmp:
        path = Path(tmp) / "scenario.yaml"
        path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
        registry = Registry.discover()
        loaded = load([ROOT / "machines" / "tararc.yaml"], registry=registry)
        top = loaded.roots[0]
        scenario, _ = load_scenario(str(path))
        world = SimWorld(World(scenario, args.seed))
        try:
            line = Timeline()
            params = machine_params(top, {})
            options = RunOptions(top.name, world.agent_names(), params, args.seed, args.max_time)
            result = run(Program(loaded.machines, registry, 0.05), world, options, line)
            scored = measure(line, list(data["robots"]), result.error)
            believed, raw = [], []
            for name, body in world.world.robots.items():
                true = world.world.truth.robot_pose(name)
                believed.append(math.dist(world.handle(name).odometry()[:2], true[:2]))
                raw.append(math.dist(body.odometry()[:2], true[:2]))
        finally:
            world.close()
    print(f"{args.robots} robots, seed {args.seed}: completed {scored['completed']}, grouped "
          f"{scored['grouped']} s, enclosed {scored['enclosed']} s, run {result.time} s")
    for label, errors in (("pose driven by (odometry + laser)", believed), ("raw odometry", raw)):
        print(f"{label}: error median {statistics.median(errors):.2f} m, max {max(errors):.2f} m")


if __name__ == "__main__":
    main()
