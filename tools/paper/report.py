"""docs/RESULTS.md: our Figure 10 beside the paper's, success rates, Figure 11, the ablations."""

from __future__ import annotations

import os
import platform
import statistics
from pathlib import Path
from typing import Any

from tools.paper.plot import failure_plot
from tools.paper.reference import (
    PAPER_LIMIT_SECONDS,
    PAPER_MEAN_MINUTES,
    PAPER_NO_WAIT_COLLISIONS,
    PAPER_NO_WAIT_MINUTES,
    SCENARIOS,
)
from tools.paper.results import (
    Row,
    by_scenario,
    failure_curve,
    figure10_markdown,
    paper_rows_markdown,
    row,
    succeeded,
)

Trials = list[dict[str, Any]]


def _rows(trials: Trials) -> list[Row]:
    grouped = by_scenario(trials)
    order = [s for s, _ in SCENARIOS if s in grouped] + sorted(set(grouped) - {s for s, _ in SCENARIOS})
    return [row(s, grouped[s]) for s in order] + [row("all", trials)]


def _summary(name: str, trials: Trials) -> str:
    ok = sum(succeeded(t) for t in trials)
    minutes = statistics.fmean(t["time"] for t in trials) / 60
    collisions = sum(t["score"]["robot_collisions"] > 0 for t in trials) / len(trials)
    dropped = sum(bool(t["score"]["dropped"]) for t in trials)
    wall = [t["wall"] for t in trials]
    return (
        f"| {name} | {len(trials)} | {ok} ({100 * ok / len(trials):.0f} %) | {minutes:.1f} | "
        f"{100 * collisions:.0f} % | {dropped} | {statistics.fmean(wall):.1f} | {max(wall):.1f} |"
    )


def _failures(trials: Trials) -> list[str]:
    lines = []
    for t in trials:
        if succeeded(t):
            continue
        s = t["score"]
        why = t["error"] or (
            f"table {s['table_wall_distance']:.2f} m from the wall, dropped={s['dropped']}, "
            f"collisions={s['robot_collisions']}, outcomes={t['outcomes']}"
        )
        lines.append(f"- {t['spec']['scenario']} seed {t['spec']['seed']}: {why}")
    return lines


def _ablations(runs: dict[str, Trials]) -> list[str]:
    base = statistics.fmean(t["time"] for t in runs["baseline"])
    paper = {
        "no_wait": f"{PAPER_NO_WAIT_MINUTES:.0f} min ({PAPER_NO_WAIT_MINUTES / PAPER_MEAN_MINUTES:.2f}x); "
        f"{100 * PAPER_NO_WAIT_COLLISIONS:.0f} % collisions",
        "margin_5": "2x the time",
    }
    lines = [
        "| ablation | paper | ours: time (x baseline) | runs with collisions | failed |",
        "|---|---|---|---|---|",
    ]
    for name, trials in runs.items():
        if name == "baseline":
            continue
        mean = statistics.fmean(t["time"] for t in trials)
        collided = sum(t["score"]["robot_collisions"] > 0 for t in trials) / len(trials)
        failed = sum(not succeeded(t) for t in trials)
        lines.append(f"| `{name}` | {paper.get(name, '-')} | {mean / 60:.1f} min ({mean / base:.2f}x) | "
                     f"{100 * collided:.0f} % | {failed}/{len(trials)} |")
    return lines


def write_report(runs: dict[str, Trials], out: Path, raw: Path, *, command: str, wall: float) -> None:
    baseline = runs["baseline"]
    plot = out.parent / "results" / "figure11.png"
    longest = max(PAPER_LIMIT_SECONDS, *(t["time"] for trials in runs.values() for t in trials))
    limits = [10.0 * k for k in range(int(longest // 10) + 3)]
    failure_plot({name: failure_curve(t, limits) for name, t in runs.items()}, plot,
                 "Figure 11: failure rate against the maximum time allowed (paper: up to 35 min)")
    text = [
        "# Results: the paper's Figure 10 and Figure 11, reproduced",
        "",
        f"Command: `.venv/bin/python {command}` ({os.cpu_count()} CPUs, Python {platform.python_version()}; "
        f"{wall / 60:.1f} min of wall time in all). Raw trials: `{raw.relative_to(out.parent.parent)}`.",
        "Every trial runs `machines/move_furniture.yaml` for two robots in the simulator, headless, at NAO",
        "speeds; a trial succeeds when the table ends within 0.15 m of a wall, never dropped, with no",
        f"robot-robot collision, within the paper's {PAPER_LIMIT_SECONDS // 60}-minute limit.",
        "",
        "| run | trials | successes | mean task min | runs with collisions | dropped | mean wall s"
        " | max wall s |",
        "|---|---|---|---|---|---|---|---|",
        *(_summary(name, trials) for name, trials in runs.items()),
        "",
        f"Paper: 60 trials, mean {PAPER_MEAN_MINUTES} min; without the waiting behaviours "
        f"{PAPER_NO_WAIT_MINUTES:.0f} min and {100 * PAPER_NO_WAIT_COLLISIONS:.0f} % collisions; "
        "with a 5 % margin instead of 20 %, twice the time.",
        "",
        "Held-out starts (robots anywhere; the table moved and turned): `docs/ROBUSTNESS.md`.",
        "",
        "## Ablations",
        "",
        *_ablations(runs),
        "",
        "## Figure 10: mean seconds per behaviour (ours)",
        "",
        "Each cell is the mean over trials of the simulated seconds spent in that behaviour (the mean over",
        "the robots that ran it). `total` is the task's time. `-`: the behaviour did not run.",
        "",
        figure10_markdown(_rows(baseline)),
        "",
        "## Figure 10 (the paper's)",
        "",
        paper_rows_markdown(),
        "",
        "## Figure 11",
        "",
        f"![failure rate against the maximum time allowed]({plot.relative_to(out.parent)})",
        "",
        "## Trials that failed",
        "",
        *(_failures(baseline) or ["None."]),
        "",
    ]
    for name, trials in runs.items():
        if name != "baseline":
            text += [f"### Ablation `{name}`: trials that failed", "", *(_failures(trials) or ["None."]), ""]
    out.write_text("\n".join(text))
