"""The bench's figures as PNGs, drawn with matplotlib (no pyplot: nothing global, same bytes)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

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
    if every or points:
        ax.legend(fontsize=8, loc="upper left")
    fig.text(0.01, 0.01, f"paper: {paper}", fontsize=7, wrap=True)
    fig.subplots_adjust(bottom=0.2)
    _save(fig, path)


def ability_plot(allocations: Sequence[Mapping[int, Mapping[str, Any]]], path: Path, title: str) -> None:
    """Figure 8 as the paper draws it: each group's ability B (x) against the difficulty of the task it
    won (y), one marker per allocation, a line joining each group's allocations in order; a task
    that failed is circled in red."""
    fig = Figure(figsize=(6.4, 4.4), dpi=100)
    ax = fig.subplots()
    markers = "os^D*v"
    for name in sorted({n for alloc in allocations for n in alloc}):
        pts = [alloc[name] for alloc in allocations if name in alloc]
        line = ax.plot([g["B"] for g in pts], [g["difficulty"] for g in pts], linewidth=1.2, alpha=0.7,
                       label=f"group {name}")[0]
        for k, alloc in enumerate(allocations):
            if name in alloc:
                g = alloc[name]
                ax.scatter([g["B"]], [g["difficulty"]], marker=markers[k % len(markers)], s=46,
                           color=line.get_color(), zorder=3)
                ax.annotate(str(k + 1), (g["B"], g["difficulty"]), textcoords="offset points", xytext=(5, 5),
                            fontsize=7)
                if not g["ok"]:
                    ax.scatter([g["B"]], [g["difficulty"]], s=220, facecolors="none", edgecolors="red",
                               linewidths=1.5, zorder=4)
    for k in range(len(allocations)):
        ax.scatter([], [], marker=markers[k % len(markers)], color="grey", label=f"allocation {k + 1}")
    ax.scatter([], [], s=120, facecolors="none", edgecolors="red", label="its task failed")
    ax.set_xlabel("group ability: B = F/C of the group's agent for the task it won (eq. 4)")
    ax.set_ylabel("difficulty of the task won")
    ax.set_ylim(0, 1)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    _save(fig, path)
