"""Test-side runner for rooms of several tables (issue 10): each robot is told, as the `table`
param of move_furniture, where the table its task names stands in its own start frame (from the
start pose the scenario gives it, not the jittered truth), and the end is judged from the truth.
With `pairs`, each robot is also told its role and runs under its pair's scope (its partner, and
a name of the pair's own)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.program import Program, machine_params
from hfsm.runtime.run import RunOptions, run
from hfsm.trace import TraceSink
from hfsm_behaviours.room import frames
from hfsm_behaviours.simworld import SimWorld
from hfsm_sim import World, load_scenario
from hfsm_sim.scenario import FailureAt, Scenario

ROOT = Path(__file__).resolve().parents[1]
TOP = ROOT / "machines" / "move_furniture.yaml"


@dataclass(frozen=True)
class RoomRun:
    outcomes: dict[str, str]
    roles: dict[str, str]
    score: dict[str, Any]
    moved: dict[str, float]  # each table's centre, metres from where it started
    outputs: dict[str, dict[str, Any]]
    ends: dict[str, list[float]]  # each table's centre at the end, room frame (the truth)
    times: dict[str, float]  # when each robot's machine ended (or it failed)
    holding: dict[str, bool]  # whose hands hold a load at the end


def _start(scenario: Scenario, robot: str) -> dict[str, float]:
    start = scenario.robots[robot]
    return {"x": start.x, "y": start.y, "yaw": start.yaw}


def in_start_frame(scenario: Scenario, robot: str, table: str) -> list[float]:
    """Where the table `table` starts, in the frame `robot` starts in (as the scenario gives it)."""
    spec = dict(zip(scenario.table_ids(), scenario.all_tables, strict=True))[table]
    return frames.to_local(_start(scenario, robot), [spec.x, spec.y])


def to_room(scenario: Scenario, robot: str, point: list[float]) -> list[float]:
    """A point in `robot`'s start frame, in the room's frame (from the start pose the scenario gives)."""
    return frames.to_room(_start(scenario, robot), point)


def pairs_told(pairs: dict[str, tuple[str, str]], channel: str = "") -> dict[str, dict[str, Any]]:
    """For each table, (leader, assistant): each robot's role, and the pair's scope (`scope`: its name,
    the table's and `channel`, and the pair), as a team would give them."""
    told: dict[str, dict[str, Any]] = {}
    for table, (leader, assistant) in pairs.items():
        scope = (f"pair_{table}{channel}", (leader, assistant))
        told[leader] = {"role": "leader", "scope": scope}
        told[assistant] = {"role": "assistant", "scope": scope}
    return told


def run_room(scenario_name: str, seed: int, tasks: dict[str, str], max_time: float = 2400.0, *,
             told: dict[str, dict[str, Any]] | None = None, radio_loss: float = 0.0,
             failures: dict[str, float] | None = None, trace: TraceSink | None = None) -> RoomRun:
    """Run move_furniture, robot `r` told to move the table `tasks[r]` (robots not in `tasks`:
    no table named) and the params `told[r]`; `failures`: robot -> the second it fails."""
    reg = Registry.discover()
    loaded = load([TOP], registry=reg)
    root = loaded.roots[0]
    scenario = load_scenario(scenario_name)
    if failures:
        scenario = scenario.model_copy(update={"failures": [FailureAt(robot=r, at=t) for r, t in failures.items()]})
    told = told or {}
    scopes = {robot: given["scope"] for robot, given in told.items() if "scope" in given}
    params = {robot: {k: v for k, v in given.items() if k != "scope"} for robot, given in told.items()}
    agent_params = {robot: machine_params(root, {"table": in_start_frame(scenario, robot, table),
                                                 **params.get(robot, {})})
                    for robot, table in tasks.items()}
    world = World(scenario, seed, radio_loss=radio_loss)
    try:
        starts = [world.truth.table_pose(i)[:2] for i in range(len(world.truth.tables))]
        options = RunOptions(root.name, list(world.robots), machine_params(root, {}), seed, max_time,
                             agent_params=agent_params, scopes=scopes)
        result = run(Program(loaded.machines, reg, 0.05), SimWorld(world), options, trace)
        ends = [world.truth.table_pose(i)[:2] for i in range(len(world.truth.tables))]
        score = world.score()
        holding = {name: bool(robot.holding()) for name, robot in world.robots.items()}
    finally:
        world.close()
    outcomes = {a: str(r.outcome) for a, r in result.agents.items()}
    roles = {a: str(r.outputs.get("role", "")) for a, r in result.agents.items()}
    moved = {t: math.dist(s, e) for t, s, e in zip(scenario.table_ids(), starts, ends, strict=True)}
    outputs = {a: dict(r.outputs) for a, r in result.agents.items()}
    times = {a: float(r.time) for a, r in result.agents.items()}
    at_end = {t: [round(float(v), 3) for v in e] for t, e in zip(scenario.table_ids(), ends, strict=True)}
    return RoomRun(outcomes, roles, score, moved, outputs, at_end, times, holding)


PAIRS = {  # scenario -> table -> (leader, assistant), as a team would form them
    "room_2_tables": {"table1": ("r1", "r2"), "table2": ("r3", "r4")},
    "room_3_pairs": {"table1": ("r1", "r2"), "table2": ("r3", "r4"), "table3": ("r5", "r6")},
    "room_5_pairs": {"table1": ("r1", "r2"), "table2": ("r3", "r4"), "table3": ("r5", "r6"),
                     "table4": ("r7", "r8"), "table5": ("r9", "r10")},
}


def run_pairs(scenario: str, seed: int, *, radio_loss: float = 0.0, failures: dict[str, float] | None = None,
              max_time: float = 2400.0) -> RoomRun:
    """Every pair of PAIRS[scenario] told its table and roles, each under its pair's scope."""
    pairs = PAIRS[scenario]
    tasks = {robot: table for table, pair in pairs.items() for robot in pair}
    return run_room(scenario, seed, tasks, max_time, told=pairs_told(pairs), radio_loss=radio_loss,
                    failures=failures)


def main(argv: list[str] | None = None) -> None:
    """One Markdown row per seed: `python tests/room_run.py room_2_tables 0-9 [--loss 0.3]`."""
    import argparse
    import time

    parser = argparse.ArgumentParser(description=main.__doc__)
    parser.add_argument("scenario", choices=sorted(PAIRS))
    parser.add_argument("seeds", help="first-last")
    parser.add_argument("--loss", type=float, default=0.0)
    parser.add_argument("--fail", action="append", default=[], help="ROBOT@SECONDS")
    args = parser.parse_args(argv)
    first, _, last = args.seeds.partition("-")
    failures = {r: float(t) for r, _, t in (f.partition("@") for f in args.fail)}
    print("| seed | outcomes | roles | wall gaps (m) | dropped | robot-robot | ends (sim s) | wall s |")
    print("|---|---|---|---|---|---|---|---|")
    cleared = 0
    seeds = range(int(first), int(last or first) + 1)
    for seed in seeds:
        start = time.monotonic()
        room = run_pairs(args.scenario, seed, radio_loss=args.loss, failures=failures)
        score = room.score
        ok = bool(score["success"])
        cleared += ok
        robots = sorted(room.outcomes, key=lambda r: (len(r), r))  # r2 before r10
        outcomes = " ".join(room.outcomes[r] for r in robots)
        roles = " ".join(room.roles[r][:1].upper() or "-" for r in robots)
        gaps = " / ".join(f"{d:.3f}" for d in score["table_wall_distances"])
        print(f"| {seed} | {outcomes} | {roles} | {gaps} | {score['dropped']} | {score['robot_collisions']} "
              f"| {' '.join(f'{room.times[r]:.0f}' for r in robots)} | {time.monotonic() - start:.0f} |",
              flush=True)
    print(f"\n{cleared} of {len(seeds)} rooms cleared (every table at a wall, no drop, no robot-robot collision)")


if __name__ == "__main__":
    main()
