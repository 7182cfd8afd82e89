"""One bench trial: a generated scenario (or a chain of runs sharing a history file, Figure 8) run
with machines/tararc.yaml in the pybullet world, scored from its trace. What sweep workers run."""

from __future__ import annotations

import math
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from hfsm_behaviours.trial import TrialSpec, run_trial
from tools.tararc.ability import failing_group, group_abilities
from tools.tararc.measure import Timeline, measure

HELP_AT = 0.3  # a failure comes this fraction of the way from grouped to enclosed (mid-move)
MACHINE = Path(__file__).resolve().parents[2] / "machines" / "tararc.yaml"


@dataclass(frozen=True)
class BenchTrial:
    """`experiment` and `x` say where the result goes; `runs` > 1 runs the scenario again that many
    times with one history file (seeds seed, seed+1, ...); in run `fail_group_in` (1-based; 0: none)
    every robot of one group fails mid-move (`group_failure`)."""

    experiment: str
    x: Any
    seed: int
    scenario: dict[str, Any]
    params: dict[str, Any] = field(default_factory=dict)
    max_time: float = 400.0
    runs: int = 1
    fail_group_in: int = 0


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
    alive = sorted(r for r in line.outcomes if r not in line.failed)
    if alive:
        out["outcomes"] = line.outcomes[alive[0]]
    return out


def group_failure(trial: BenchTrial, scenario: dict[str, Any], seed: int, folder: Path,
                  params: dict[str, Any]) -> list[dict[str, Any]]:
    """Every robot of the group that wins the second hardest task (`ability.failing_group`) failing
    `HELP_AT` of the way from grouped to enclosed. Which group and when come from a run of the same
    seed without the failure (the failure run repeats it exactly up to then), on a copy of the
    history: the file is as it was afterwards."""
    history = Path(params["history"]) if params.get("history") else None
    kept = history.read_bytes() if history and history.exists() else None
    dry = _one_run(trial, scenario, seed, folder, params)
    if history:
        if kept is None:
            history.unlink(missing_ok=True)
        else:
            history.write_bytes(kept)
    if not dry.get("groups") or not math.isfinite(dry["enclosed"]):
        return []
    at = round(dry["grouped"] + HELP_AT * (dry["enclosed"] - dry["grouped"]), 2)
    members = dry["groups"][failing_group(dry["groups"])]["members"]
    return [{"robot": m, "at": at, "reason": "bench: its whole group fails"} for m in members]


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
            if trial.fail_group_in == k + 1:
                failing = group_failure(trial, scenario, trial.seed + k, folder, params)
                scenario["failures"] = [*scenario.get("failures", []), *failing]
            runs.append(_one_run(trial, scenario, trial.seed + k, folder, params))
    head = {"experiment": trial.experiment, "x": trial.x, "seed": trial.seed}
    return {**head, **runs[0]} if trial.runs == 1 else {**head, "runs": runs}
