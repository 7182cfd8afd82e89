"""One campaign trial: a generated room run with machines/clear_room.yaml, judged by the scorer."""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from behaviours.trial import TrialSpec, run_trial
from tools.room.scenes import room

MACHINE = Path(__file__).resolve().parents[2] / "machines" / "clear_room.yaml"
CLEAR = 0.15  # metres: a table this near a wall is at it (the scorer's success distance)


@dataclass(frozen=True)
class RoomTrial:
    k: int
    n: int
    seed: int
    failure: str = "none"
    loss: float = 0.0
    max_time: float = 2100.0  # 35 simulated minutes


def run_room_trial(trial: RoomTrial) -> dict[str, Any]:
    """Whether every table reached a wall, when, and what went wrong on the way."""
    from hfsm.cli.quiet import stdout_to_stderr

    scenario = room(trial.k, trial.n, trial.seed, trial.failure)
    with stdout_to_stderr(), tempfile.TemporaryDirectory(prefix="room-bench-") as tmp:
        path = Path(tmp) / "room.yaml"
        path.write_text(yaml.safe_dump(scenario, sort_keys=False), encoding="utf-8")
        spec = TrialSpec(str(MACHINE), str(path), trial.seed, {}, trial.max_time, radio_loss=trial.loss)
        result = run_trial(spec)
    score = result.score
    gaps = score.get("table_wall_distances") or [score.get("table_wall_distance")]
    failed = [f["robot"] for f in scenario.get("failures", [])]
    alive = {a: o for a, o in result.outcomes.items() if a not in failed}
    return {
        "k": trial.k, "n": trial.n, "seed": trial.seed, "failure": trial.failure, "loss": trial.loss,
        "failed": failed,
        "cleared": all(g is not None and g <= CLEAR for g in gaps),
        "all_said_cleared": all(o == "cleared" for o in alive.values()),
        "tables_at_wall": sum(1 for g in gaps if g is not None and g <= CLEAR),
        "time": result.time, "collisions": score.get("robot_collisions", 0),
        "error": result.error, "wall": round(result.wall, 1),
    }
