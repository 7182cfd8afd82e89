"""Counterexamples: a run's choices as a schedule, and the run replayed with them into a trace.

The file is a trace (`hfsm-monitor` shows it) whose first line is the schedule: a record of kind
`schedule` with an empty path. `hfsm-run FILE --world none --replay CE.jsonl --trace OUT.jsonl`
runs the same program with the same choices and writes the same bytes.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from hfsm.errors import UsageError
from hfsm.load import Loaded
from hfsm.registry import Registry
from hfsm.runtime.failing import Failure
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.trace import TraceSink
from hfsm.verify.build import verify_program
from hfsm.verify.choices import Schedule
from hfsm.verify.radio import ChoosingWorld
from hfsm.verify.values import Values

KIND = "schedule"


def schedule_record(setup: dict[str, Any]) -> dict[str, Any]:
    return {"t": 0, "agent": "", "path": [], "kind": KIND, "verify": setup}


def read_schedule(path: Path) -> dict[str, Any]:
    """The schedule of a counterexample file (UsageError if it has none)."""
    try:
        with path.open(encoding="utf-8") as f:
            first = json.loads(f.readline() or "{}")
    except (OSError, json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise UsageError(f"--replay {path}: cannot read a counterexample: {exc}") from None
    if not isinstance(first, dict) or first.get("kind") != KIND or not isinstance(first.get("verify"), dict):
        raise UsageError(
            f"--replay {path}: not a counterexample of hfsm-verify (no schedule on its first line)"
        )
    setup: dict[str, Any] = first["verify"]
    return setup


def replay(loaded: Loaded, registry: Registry, setup: dict[str, Any], sink: TraceSink | None) -> RunResult:
    """Run the schedule's program with its choices; `sink` gets the schedule, then the trace."""
    values = Values(setup.get("outputs", {}), setup.get("inputs", {}), setup.get("scripts", {}))
    decider = Schedule(setup["choices"])
    dt = float(setup["dt"])
    program = verify_program(loaded, registry, list(setup["stand_ins"]), values, decider, dt)
    world = ChoosingWorld(decider, 0, 0, 0, values.inputs)
    failures = [Failure(a, c["t"]) for c in setup["choices"] if c["kind"] == "fail" for a in c["agents"]]
    options = RunOptions(
        setup["top"],
        list(setup["agents"]),
        dict(setup["params"]),
        int(setup["seed"]),
        float(setup["bound"]),
        failures,
        dict(setup.get("agent_params", {})),
        scopes={a: (str(n), tuple(m)) for a, (n, m) in setup.get("scopes", {}).items()},
    )
    if sink is not None:
        sink.write(schedule_record(setup))
    return run(program, world, options, sink)
