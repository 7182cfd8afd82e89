"""The campaign's results as Markdown lines and matplotlib PNGs (no pyplot: nothing global)."""

from __future__ import annotations

import statistics
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from matplotlib.figure import Figure

Result = dict[str, Any]


def _key(r: Result) -> tuple[int, int, str, float]:
    return (r["k"], r["n"], r["failure"], r["loss"])


def table_lines(results: Sequence[Result]) -> list[str]:
    rows = ["| K tables | N robots | failure | radio loss | cleared | median sim time (s) | max sim time (s) "
            "| robot-robot collisions | median wall (s) |", "|---|---|---|---|---|---|---|---|---|"]
    groups: dict[tuple[int, int, str, float], list[Result]] = {}
    for r in results:
        groups.setdefault(_key(r), []).append(r)
    for (k, n, failure, loss), rs in sorted(groups.items()):
        done = [r for r in rs if r["cleared"]]
        times = [r["time"] for r in done]
        med = f"{statistics.median(times):.0f}" if times else "-"
        top = f"{max(times):.0f}" if times else "-"
        rows.append(f"| {k} | {n} | {failure} | {loss:g} | {len(done)}/{len(rs)} | {med} | {top} | "
                    f"{sum(r['collisions'] for r in rs)} | {statistics.median(r['wall'] for r in rs):.0f} |")
    return rows


LABELS = {"none": "no failure", "early": "one robot failing on its way to its table (2-12 s)",
          "mid": "one robot failing in the carry (50-90 s)"}


def summary_lines(results: Sequence[Result]) -> list[str]:
    out = []
    for kind, label in LABELS.items():
        rs = [r for r in results if r["failure"] == kind]
        if rs:
            done = sum(r["cleared"] for r in rs)
            out.append(f"- {label}: {done} of {len(rs)} rooms cleared within 35 simulated minutes.")
    out.append(f"- Robot-robot contact episodes over all {len(results)} rooms: "
               f"{sum(r['collisions'] for r in results)}.")
    return out


def _save(fig: Figure, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, metadata={"Software": None})


def time_plot(results: Sequence[Result], path: Path) -> None:
    """Simulated time to clear the room against the number of robots, one colour per K."""
    fig = Figure(figsize=(6.4, 4.0), dpi=100)
    ax = fig.subplots()
    for k in sorted({r["k"] for r in results}):
        done = [r for r in results if r["k"] == k and r["cleared"]]
        marks = {"none": "o", "early": "s", "mid": "^"}
        for failure, mark in marks.items():
            pts = [(r["n"], r["time"]) for r in done if r["failure"] == failure]
            if pts:
                ax.scatter([p[0] for p in pts], [p[1] for p in pts], marker=mark, label=f"K={k}, {failure}")
    ax.set_xlabel("robots N")
    ax.set_ylabel("simulated seconds to clear the room")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Time to clear the room (rooms cleared only)", fontsize=10)
    _save(fig, path)


def success_plot(results: Sequence[Result], path: Path) -> None:
    """The share of rooms cleared, by failure kind."""
    kinds = [k for k in ("none", "early", "mid") if any(r["failure"] == k for r in results)]
    shares = []
    for kind in kinds:
        rs = [r for r in results if r["failure"] == kind]
        shares.append(sum(r["cleared"] for r in rs) / len(rs))
    fig = Figure(figsize=(5.0, 3.4), dpi=100)
    ax = fig.subplots()
    ax.bar(kinds, shares, color=["#4c72b0", "#dd8452", "#c44e52"][: len(kinds)])
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("rooms cleared")
    ax.set_xlabel("robot failure")
    ax.set_title("Rooms cleared within 35 simulated minutes", fontsize=10)
    _save(fig, path)
