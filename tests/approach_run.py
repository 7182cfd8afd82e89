"""Test-side runner for the approach: run machines in a sim world, then judge the end state
from the simulator's ground truth (tests may read it; behaviours never do)."""

from __future__ import annotations

import math
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hfsm.load import load
from hfsm.primitive import Context, primitive
from hfsm.registry import Registry
from hfsm.runtime.program import Program, machine_params
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.trace import ListTrace
from hfsm_behaviours.simworld import SimWorld
from hfsm_sim import World, load_scenario
from hfsm_sim.profile import DEFAULT_BODY

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "behaviours" / "data"


@dataclass(frozen=True)
class Placement:
    """A robot against the table, in the table's frame: `along` from the middle of its side,
    `depth` of its hands under the edge (m, positive under), `yaw` off square, `side` +1/-1
    for the long side (0: not at a long side)."""

    along: float
    depth: float
    yaw: float
    side: int


def placement(world: World, name: str) -> Placement:
    truth = world.truth
    tx, ty, _, tyaw = truth.table_pose()
    x, y, yaw = truth.robot_pose(name)
    c, s = math.cos(tyaw), math.sin(tyaw)
    lx, ly = c * (x - tx) + s * (y - ty), -s * (x - tx) + c * (y - ty)
    spec = truth.table.spec
    side = 1 if ly > 0 else -1
    if abs(lx) > spec.length / 2:
        return Placement(lx, -math.inf, math.nan, 0)
    depth = DEFAULT_BODY.hand_x - (abs(ly) - spec.width / 2)
    facing = math.atan2(-side, 0.0)
    off = (yaw - tyaw - facing + math.pi) % (2 * math.pi) - math.pi
    return Placement(lx, depth, off, side)


def distances(world: World) -> dict[str, float]:
    """Centre to centre: each robot to the table (`r1_table`) and to each other (`r1_r2`)."""
    truth = world.truth
    tx, ty = truth.table_pose()[:2]
    poses = {n: truth.robot_pose(n) for n in world.robots}
    out = {f"{n}_table": math.hypot(p[0] - tx, p[1] - ty) for n, p in poses.items()}
    for a, pa in poses.items():
        for b, pb in poses.items():
            if a != b:
                out[f"{a}_{b}"] = math.hypot(pa[0] - pb[0], pa[1] - pb[1])
    return out


def corner_distance(world: World, name: str) -> float:
    x, y, _ = world.truth.robot_pose(name)
    return min(math.hypot(c[0] - x, c[1] - y) for c in world.truth.table_corners())


@primitive(outcomes=["held", "not_held"], world="sim")
def lift_check(ctx: Context, *, height: float = 0.34, hold: float = 1.0) -> str:
    """Test only: raise the hands a little, report whether they hold the table, lower them."""
    ctx.robot.arms_lift(height)
    ctx.wait(hold)
    held = bool(ctx.robot.holding())
    ctx.robot.arms_lower()
    ctx.wait(hold)
    return "held" if held else "not_held"


def registry() -> Registry:
    reg = Registry.discover()
    reg.add(lift_check)
    return reg


def approach_library(folder: Path, stub: Path = DATA / "move_table.yaml") -> Path:
    """A copy of machines/ in `folder` with `stub` as move_table: the approach runs alone."""
    for path in sorted((ROOT / "machines").glob("*.yaml")):
        if path.name != "move_table.yaml":
            shutil.copy(path, folder / path.name)
    shutil.copy(stub, folder / "move_table.yaml")
    return folder / "move_furniture.yaml"


def run_machine(top: Path, scenario: str, seed: int, *, extra: list[Path] | None = None,
                params: dict[str, Any] | None = None, max_time: float = 900.0,
                reg: Registry | None = None) -> tuple[RunResult, list[dict[str, Any]], dict[str, Any]]:
    """Run `top` (with `extra` machine files' folders searched first) and judge the end."""
    reg = reg or registry()
    loaded = load([top, *(extra or [])], registry=reg)
    root = loaded.roots[0]
    full = machine_params(root, params or {})
    world = World(load_scenario(scenario), seed)
    try:
        start = distances(world)
        program = Program(loaded.machines, reg, 0.05)
        trace = ListTrace()
        options = RunOptions(root.name, list(world.robots), full, seed, max_time)
        result = run(program, SimWorld(world), options, trace)
        judged = {"score": world.score(), "start": start, "end": distances(world),
                  "placements": {n: placement(world, n) for n in world.robots},
                  "corner_distance": {n: corner_distance(world, n) for n in world.robots}}
    finally:
        world.close()
    return result, trace.records, judged


def exit_time(records: list[dict[str, Any]], agent: str, state: str) -> float | None:
    for r in records:
        if r["agent"] == agent and r["kind"] == "exit" and r["path"][-1] == state:
            return float(r["t"])
    return None
