"""One bench trial: a generated room run with machines/clear_room.yaml in the pybullet world (the run
API hfsm-run uses: hfsm_behaviours.trial.run_trial), headless, no video, its outcome read off the scorer
and the trace only. What sweep workers run."""

from __future__ import annotations

import tempfile
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from hfsm_behaviours.trial import TrialSpec, run_trial

MACHINE = Path(__file__).resolve().parents[2] / "machines" / "clear_room.yaml"
CARRY_ENDS = ("finished", "give_up")  # clear_room's states that append to vars.carries
LIFT = "lift_table"  # a robot calling it lifts its table: the carry has begun
ROUTINE = frozenset({"done", "sent", "join", "stopped", "passed", "heard", "received", "stepped", "lifted",
                     "landed", "measured", "centred", "aligned", "found", "seen", "chosen", "colour"})


@dataclass(frozen=True)
class RoomTrial:
    """`experiment` (the stratum) and `x` say where the result goes; the room is `scenario`
    (hfsm_sim.roomgen); `radio_loss` 0 leaves the scenario's own."""

    experiment: str
    x: Any
    seed: int
    scenario: dict[str, Any]
    radio_loss: float = 0.0
    max_time: float = 2100.0


@dataclass
class RoomLine:
    """A trace sink (hfsm.trace.TraceSink) keeping what the bench scores: failures, the carries as
    they end (clear_room's `finished`/`give_up`), each robot's first lift and last job, and for the
    story of a run that fails, how each robot's behaviours under `work` ended."""

    failed: dict[str, float] = field(default_factory=dict)
    carries: list[dict[str, Any]] = field(default_factory=list)
    lifted: dict[str, float] = field(default_factory=dict)
    role: dict[str, str] = field(default_factory=dict)
    endings: dict[str, Counter[str]] = field(default_factory=dict)
    stuck: dict[str, str] = field(default_factory=dict)  # robot -> why no pair is left (its job)

    def write(self, record: dict[str, Any]) -> None:
        kind, path, agent = record["kind"], record["path"], record["agent"]
        if kind == "failed":
            self.failed.setdefault(agent, record["t"])
        elif kind == "enter" and record.get("do") == LIFT:
            self.lifted.setdefault(agent, record["t"])
        elif (kind == "exit" and len(path) > 4 and path[1] == "work" and path[2] == "carry"
              and str(record.get("event")).isidentifier() and record.get("event") not in ROUTINE):
            self.endings.setdefault(agent, Counter())[f"{path[-1]}:{record.get('event')}"] += 1
        elif kind == "event" and len(path) == 2:
            values = record.get("vars", {})
            job = values.get("job")
            if isinstance(job, dict) and job.get("role") == "stuck":
                self.stuck[agent] = str(job.get("why", ""))
            elif isinstance(job, dict) and job.get("role"):
                self.role[agent] = str(job["role"])
            if path[1] in CARRY_ENDS and values.get("carries"):
                self.carries.append({"t": record["t"], "agent": agent, **values["carries"][-1]})

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


def cleared_at(carries: list[dict[str, Any]], tables: list[str]) -> float | None:
    """When the last table first reached its wall (a carry ending `at_wall`), or None if one never did."""
    first: dict[str, float] = {}
    for c in carries:
        if c["outcome"] == "at_wall":
            first.setdefault(c["table"], c["t"])
    return max(first[t] for t in tables) if all(t in first for t in tables) else None


def phase(line: RoomLine, robot: str, at: float) -> str:
    """What the failed robot was doing: `spare` (never in a pair), `before lift`, `mid-carry`, or
    `after its table` (its carry had ended at a wall); `not reached` if the run ended before."""
    if robot not in line.failed:
        return "not reached"
    if any(c["agent"] == robot and c["outcome"] == "at_wall" and c["t"] <= at for c in line.carries):
        return "after its table"
    if line.role.get(robot) not in ("leader", "assistant"):
        return "spare"
    return "mid-carry" if line.lifted.get(robot, float("inf")) <= at else "before lift"


def failures_of(line: RoomLine, scenario: dict[str, Any]) -> list[dict[str, Any]]:
    """Every robot that failed, in time order, with what it was doing (`phase`); a failure the scenario
    names (`at:`) that the run ended before is listed as `not reached`. The `rate:` form names no time:
    only the failures that happened are listed."""
    seen = sorted(line.failed.items(), key=lambda item: (item[1], item[0]))
    out = [{"robot": robot, "at": at, "phase": phase(line, robot, at)} for robot, at in seen]
    out += [{"robot": f["robot"], "at": f["at"], "phase": "not reached"}
            for f in scenario.get("failures", []) if "robot" in f and f["robot"] not in line.failed]
    return out


def measure(line: RoomLine, result_score: dict[str, Any], scenario: dict[str, Any],
            outcomes: dict[str, str | None], time: float, error: str | None) -> dict[str, Any]:
    """What the bench keeps of a run. `success`: cleared with no robot-robot contact. `honest`: not
    cleared, but every robot alive ended `stuck` before the time limit (no pair was left for a table;
    `stuck` says which and why), with no contact: reported apart from the rooms that failed."""
    tables = [str(t["id"]) for t in scenario["tables"]]
    distances = result_score.get("table_wall_distances") or [result_score["table_wall_distance"]]
    at_walls = all(d is not None and d <= 0.15 for d in distances)
    failures = failures_of(line, scenario)
    # The failure model: a robot failing mid-carry drops what it holds. That fall is the
    # failure's, not the team's; any other drop (a pair losing its table) still fails the room.
    dropped_by_failure = bool(result_score["dropped"]) and any(f["phase"] == "mid-carry" for f in failures)
    cleared = at_walls and (not result_score["dropped"] or dropped_by_failure)
    stuck = sorted(set(line.stuck.values()))
    timed_out = bool(error and "max-time" in error)
    out: dict[str, Any] = {
        "cleared": cleared, "clear_time": cleared_at(line.carries, tables) if cleared else None,
        "time": time, "error": error, "distances": distances, "dropped": result_score["dropped"],
        "dropped_by_failure": dropped_by_failure, "collisions": result_score["robot_collisions"],
        "outcomes": outcomes, "carries": [dict(c) for c in line.carries],
        "success": cleared and result_score["robot_collisions"] == 0,
        "honest": (not cleared and not timed_out and result_score["robot_collisions"] == 0 and bool(stuck)
                   and all(o in ("stuck", None) for o in outcomes.values())),
        "stuck": stuck,
        "failed": line.failed, "failures": [{**f, "recovered": cleared} for f in failures],
    }
    if failures:
        out["failure"] = out["failures"][0]
    if not cleared:
        out["endings"] = {a: dict(sorted(c.items())) for a, c in sorted(line.endings.items())}
    return out


def run_room_trial(trial: RoomTrial) -> dict[str, Any]:
    """The trial's measures; `wall` (seconds) is the only part that changes from machine to machine."""
    from hfsm.cli.quiet import stdout_to_stderr

    with stdout_to_stderr(), tempfile.TemporaryDirectory(prefix="room-bench-") as tmp:
        path = Path(tmp) / f"room-{trial.seed}.yaml"
        path.write_text(yaml.safe_dump(trial.scenario, sort_keys=False), encoding="utf-8")
        line = RoomLine()
        spec = TrialSpec(str(MACHINE), str(path), trial.seed, {}, trial.max_time, radio_loss=trial.radio_loss)
        result = run_trial(spec, line)
    sc = trial.scenario
    loss = trial.radio_loss or float(sc.get("radio", {}).get("loss", 0.0))
    head = {"experiment": trial.experiment, "x": trial.x, "seed": trial.seed, "k": len(sc["tables"]),
            "n": len(sc["robots"]), "loss": loss, "max_time": trial.max_time,
            "room": [sc["room"]["width"], sc["room"]["depth"]],
            "tables": [str(t["id"]) for t in sc["tables"]]}
    return {**head, **measure(line, result.score, sc, result.outcomes, result.time, result.error),
            "wall": round(result.wall, 2)}
