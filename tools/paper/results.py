"""Trial results folded into the paper's shapes: Figure 10's table, the success rate, Figure 11's curve."""

from __future__ import annotations

import statistics
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from tools.paper.reference import BEHAVIOURS, PAPER, PAPER_LIMIT_SECONDS, SCENARIOS

Trial = dict[str, Any]  # TrialResult.as_dict()


def succeeded(trial: Trial, limit: float = PAPER_LIMIT_SECONDS) -> bool:
    score = trial["score"]
    return bool(score["success"]) and not score["dropped"] and score["robot_collisions"] == 0 and (
        trial["time"] <= limit
    )


def behaviour_seconds(trial: Trial, behaviour: str) -> float | None:
    """Mean, over the agents that ran it, of the simulated seconds spent in one behaviour."""
    spent = [table[behaviour] for table in trial["seconds"].values() if behaviour in table]
    return statistics.fmean(spent) if spent else None


@dataclass(frozen=True)
class Row:
    scenario: str
    trials: int
    successes: int
    per_behaviour: tuple[float | None, ...]
    mean_time: float
    collisions: float  # fraction of trials with a robot-robot collision
    mean_wall: float


def row(scenario: str, trials: Sequence[Trial]) -> Row:
    columns = []
    for behaviour in BEHAVIOURS:
        values = [v for t in trials if (v := behaviour_seconds(t, behaviour)) is not None]
        columns.append(statistics.fmean(values) if values else None)
    return Row(
        scenario,
        len(trials),
        sum(succeeded(t) for t in trials),
        tuple(columns),
        statistics.fmean(t["time"] for t in trials),
        sum(t["score"]["robot_collisions"] > 0 for t in trials) / len(trials),
        statistics.fmean(t["wall"] for t in trials),
    )


def by_scenario(trials: Iterable[Trial]) -> dict[str, list[Trial]]:
    grouped: dict[str, list[Trial]] = {}
    for trial in trials:
        grouped.setdefault(trial["spec"]["scenario"], []).append(trial)
    return grouped


def failure_curve(trials: Sequence[Trial], limits: Sequence[float]) -> list[tuple[float, float]]:
    """Figure 11: the fraction of trials not done within each time limit."""
    return [(limit, sum(not succeeded(t, limit) for t in trials) / len(trials)) for limit in limits]


def figure10_markdown(rows: Sequence[Row]) -> str:
    head = ["start position", *BEHAVIOURS, "total s", "total min", "paper min"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    names = dict(SCENARIOS)
    for r in rows:
        cells = ["-" if v is None else f"{v:.0f}" for v in r.per_behaviour]
        paper = PAPER.get(r.scenario)
        paper_min = f"{paper[2]:.1f}" if paper else "-"
        label = names.get(r.scenario, r.scenario)
        total = f" | {r.mean_time:.0f} | {r.mean_time / 60:.1f} | {paper_min} |"
        lines.append(f"| {label} | " + " | ".join(cells) + total)
    return "\n".join(lines)


def paper_rows_markdown() -> str:
    head = ["start position", *BEHAVIOURS, "total s", "total min"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for key, label in SCENARIOS:
        values, total, minutes = PAPER[key]
        lines.append(f"| {label} | " + " | ".join(str(v) for v in values) + f" | {total} | {minutes} |")
    return "\n".join(lines)
