"""The bench's figures as PNGs, drawn with matplotlib (no pyplot: nothing global, same bytes)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from matplotlib.figure import Figure

Point = tuple[float, float]


def _save(fig: Figure, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, metadata={"Software": None})


def curve_plot(points: Sequence[Point], every: Sequence[Point], path: Path, *, xlabel: str, ylabel: str,
               title: str, paper: str) -> None:
    """Our medians as a line, every trial as a dot, and what the paper says as the caption."""
    fig = Figure(figsize=(6.4, 4.2), dpi=100)
    ax = fig.subplots()
    if every:
        ax.scatter([x for x, _ in every], [y for _, y in every], s=12, color="grey", alpha=0.6,
                   label="ours: each trial")
    if points:
        ax.plot([x for x, _ in points], [y for _, y in points], marker="o", linewidth=2,
                label="ours: median")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_ylim(bottom=0)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.text(0.01, 0.01, f"paper: {paper}", fontsize=7, wrap=True)
    fig.subplots_adjust(bottom=0.2)
    _save(fig, path)


def ability_plot(runs: Sequence[Sequence[Point]], path: Path, title: str) -> None:
    """Figure 8: for each of the successive allocations (one marker each), every group's B against
    the difficulty of the task it won; a line joins each group's points across allocations."""
    fig = Figure(figsize=(6.4, 4.2), dpi=100)
    ax = fig.subplots()
    markers = "os^D*v"
    groups = max((len(r) for r in runs), default=0)
    for g in range(groups):
        pts = [run[g] for run in runs if g < len(run)]
        ax.plot([b for b, _ in pts], [d for _, d in pts], linewidth=1, alpha=0.5, label=f"group {g}")
    for k, run in enumerate(runs):
        ax.scatter([b for b, _ in run], [d for _, d in run], marker=markers[k % len(markers)], s=40,
                   label=f"allocation {k + 1}", zorder=3)
    ax.set_xlabel("group ability: B = F/C of the group's agent for the task it won (eq. 4)")
    ax.set_ylabel("difficulty of the task won")
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    _save(fig, path)
