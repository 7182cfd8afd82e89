"""Test-side helpers for the carry: small scenes with robots at the table, one primitive or
machine run in them, and the end judged from ground truth (tests may read it; behaviours never)."""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.program import Program, machine_params
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.trace import ListTrace
from hfsm_behaviours.simworld import SimWorld
from hfsm_sim import World, load_scenario, scenario_from_dict
from hfsm_sim.profile import DEFAULT_BODY

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "behaviours" / "data" / "carry"
TABLE_X = 0.6
GRIP_Y = 0.25 + DEFAULT_BODY.hand_x - 0.08  # hands 8 cm under the 0.5 m wide table's edge


def at_table(r1: tuple[float, float, float] = (0.0, 0.0, 0.0),
             r2: tuple[float, float, float] | None = (0.0, 0.0, 0.0),
             table_x: float = TABLE_X) -> dict[str, Any]:
    """A scenario dict: robots at the middles of the long sides, each moved by (along the
    table m, away from it m, turned degrees) from square at grip depth."""
    robots = {"r1": {"x": table_x + r1[0], "y": -GRIP_Y - r1[1], "yaw": 90.0 + r1[2]}}
    if r2 is not None:
        robots["r2"] = {"x": table_x + r2[0], "y": GRIP_Y + r2[1], "yaw": -90.0 + r2[2]}
    return {"room": {"width": 5.0, "depth": 5.0}, "table": {"x": table_x}, "robots": robots}


@dataclass(frozen=True)
class Pose:
    """A robot against the table, in the table's frame: `along` the long axis from the middle
    (m), `depth` of its hands under the edge (m), `yaw` off square (degrees)."""

    along: float
    depth: float
    yaw: float


def pose(world: World, name: str) -> Pose:
    tx, ty, _, tyaw = world.truth.table_pose()
    x, y, yaw = world.truth.robot_pose(name)
    c, s = math.cos(tyaw), math.sin(tyaw)
    along, across = c * (x - tx) + s * (y - ty), -s * (x - tx) + c * (y - ty)
    depth = DEFAULT_BODY.hand_x - (abs(across) - world.truth.table.spec.width / 2)
    facing = math.pi / 2 if across < 0 else -math.pi / 2
    off = (yaw - tyaw - facing + math.pi) % (2 * math.pi) - math.pi
    return Pose(along, depth, math.degrees(off))


@dataclass
class Outcome:
    result: RunResult
    records: list[dict[str, Any]]
    score: dict[str, Any]
    poses: dict[str, Pose]
    table: tuple[float, float, float, float]

    def outcome(self, agent: str = "r1") -> str | None:
        return self.result.agents[agent].outcome

    def outputs(self, agent: str = "r1") -> dict[str, Any]:
        return dict(self.result.agents[agent].outputs)


def machine_file(folder: Path, text: str, name: str = "probe") -> Path:
    path = folder / f"{name}.yaml"
    path.write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    return path


def run_in_scene(top: Path, scenario: dict[str, Any] | str, *, seed: int = 0,
                 params: dict[str, Any] | None = None, max_time: float = 600.0,
                 radio_latency: float = 0.1) -> Outcome:
    """Run the machine file `top` (machines/ searched after its folder) in a sim world."""
    reg = Registry.discover()
    loaded = load([top], registry=reg)
    root = loaded.roots[0]
    full = machine_params(root, params or {})
    spec = load_scenario(scenario) if isinstance(scenario, str) else scenario_from_dict(scenario)
    world = World(spec, seed, radio_latency=radio_latency)
    try:
        trace = ListTrace()
        options = RunOptions(root.name, list(world.robots), full, seed, max_time)
        result = run(Program(loaded.machines, reg, 0.05), SimWorld(world), options, trace)
        poses = {n: pose(world, n) for n in world.robots}
        return Outcome(result, trace.records, world.score(), poses, world.truth.table_pose())
    finally:
        world.close()
