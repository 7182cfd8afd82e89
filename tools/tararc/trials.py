"""One bench trial: a generated scenario (or a chain of runs sharing a history file, Figure 8) run
with machines/tararc.yaml in the pybullet world, scored from its trace. What sweep workers run."""

from __future__ import annotations

import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from behaviours.tararc.formulas import belief, efficiency
from behaviours.tararc.grouping import Robot, distance
from behaviours.tararc.history import p_term
from behaviours.tararc.plan import history_of
from behaviours.trial import TrialSpec, run_trial
from tools.tararc.measure import Timeline, measure

MACHINE = Path(__file__).resolve().parents[2] / "machines" / "tararc.yaml"


@dataclass(frozen=True)
class BenchTrial:
    """`experiment` and `x` say where the result goes; `runs` > 1 runs the scenario again that many
    times with one history file (seeds seed, seed+1, ...), `fail_in_run` adds `failures` to that run
    only (1-based; 0: to every run)."""

    experiment: str
    x: Any
    seed: int
    scenario: dict[str, Any]
    params: dict[str, Any] = field(default_factory=dict)
    max_time: float = 400.0
    runs: int = 1
    failures: tuple[dict[str, Any], ...] = ()
    fail_in_run: int = 0


def group_abilities(first: dict[str, Any]) -> list[dict[str, float]]:
    """Each group's B (eq. 4) for the task it won, and that task's difficulty (Figure 8), from the
    plan the team made: the history the robots said, their energy and start, the agent's place 0."""
    history = history_of({r: {"record": rec} for r, rec in first["records"].items()})
    out = []
    for g in first["groups"]:
        agent, task = first["robots"][g["agent"]], g["task"]
        f = belief(p_term(history, g["agent"]), task["difficulty"], agent["energy"], 0)
        gap = distance(Robot(g["agent"], agent["x"], agent["y"]), Robot(task["id"], task["x"], task["y"]))
        out.append({"B": round(efficiency(f, gap, task["difficulty"]), 4), "difficulty": task["difficulty"]})
    return out


def _one_run(trial: BenchTrial, scenario: dict[str, Any], seed: int, folder: Path,
             params: dict[str, Any]) -> dict[str, Any]:
    path = folder / f"scenario-{seed}.yaml"
    path.write_text(yaml.safe_dump(scenario, sort_keys=False), encoding="utf-8")
    line = Timeline()
    result = run_trial(TrialSpec(str(MACHINE), str(path), seed, params, trial.max_time), line)
    out = measure(line, list(scenario["robots"]), result.error)
    out.update(time=result.time, error=result.error, collisions=result.score.get("robot_collisions", 0),
               wall=round(result.wall, 2))
    if line.first:
        out["groups"] = group_abilities(line.first)
        out["agents"] = [g["agent"] for g in line.first["groups"]]
    return out


def run_bench_trial(trial: BenchTrial) -> dict[str, Any]:
    """The trial's measures (one run, or `runs` runs as a list); wall seconds are the only part
    that changes from one machine to another."""
    from hfsm.cli.quiet import stdout_to_stderr

    with stdout_to_stderr(), tempfile.TemporaryDirectory(prefix="tararc-bench-") as tmp:
        folder = Path(tmp)
        params = dict(trial.params)
        if trial.runs > 1:
            params["history"] = str(folder / "history.json")
        runs = []
        for k in range(trial.runs):
            scenario = dict(trial.scenario)
            if trial.failures and trial.fail_in_run in (0, k + 1):
                scenario["failures"] = [*scenario.get("failures", []), *trial.failures]
            runs.append(_one_run(trial, scenario, trial.seed + k, folder, params))
    head = {"experiment": trial.experiment, "x": trial.x, "seed": trial.seed}
    return {**head, **runs[0]} if trial.runs == 1 else {**head, "runs": runs}
