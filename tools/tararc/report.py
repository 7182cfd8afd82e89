"""The bench's results as Markdown tables beside the paper's, and its figures, in docs/TARARC.md."""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from tools.docsection import write_section
from tools.tararc.experiments import PAPER_SAYS, PAPER_TABLE1
from tools.tararc.plots import ability_plot, curve_plot

Results = list[dict[str, Any]]


def median(values: Sequence[float]) -> float:
    """The median of the finite values; inf when there are none (nothing finished)."""
    finite = [v for v in values if math.isfinite(v)]
    return statistics.median(finite) if finite else math.inf


def seconds(value: float) -> str:
    return f"{value:.1f}" if math.isfinite(value) else "∞"


def by_x(results: Results, experiment: str) -> dict[Any, Results]:
    out: dict[Any, Results] = {}
    for r in results:
        if r["experiment"] == experiment:
            out.setdefault(str(r["x"]) if isinstance(r["x"], list) else r["x"], []).append(r)
    return out


def timed(rs: Results, key: str) -> list[float]:
    """The times of `key` to take the median of: of the runs that completed, but for the time to
    group, which is of every run that grouped (a task missed later does not undo the grouping)."""
    if key == "grouped":
        return [r[key] for r in rs if math.isfinite(r[key])]
    return [r[key] for r in rs if r["completed"] and math.isfinite(r[key])]


def _row(rs: Results, key: str) -> str:
    done = [r for r in rs if r["completed"]]
    hits = sum(r["collisions"] for r in rs)
    return f"{seconds(median(timed(rs, key)))} | {len(done)}/{len(rs)} | {hits}"


def table1(results: Results) -> list[str]:
    lines = ["| priorities of (t1, t2, t3) | paper: convergence (s) | ours: median convergence (s) "
             "| completed | robot-robot collisions |", "|---|---|---|---|---|"]
    for order, paper in PAPER_TABLE1.items():
        rs = by_x(results, "table1").get(str(list(order)), [])
        if rs:
            lines.append(f"| {order} | {seconds(paper)} | {_row(rs, 'converge')} |")
    return lines


Points = list[tuple[float, float]]


def curve(results: Results, experiment: str, key: str, label: str) -> tuple[list[str], Points, Points]:
    lines = [f"| {label} | ours: median (s) | completed | robot-robot collisions |", "|---|---|---|---|"]
    points: Points = []
    every: Points = []
    for x, rs in sorted(by_x(results, experiment).items()):
        lines.append(f"| {x} | {_row(rs, key)} |")
        done = timed(rs, key)
        every += [(float(x), v) for v in done]
        if done:
            points.append((float(x), median(done)))
    return lines, points, every


def growth(points: Points) -> str:
    """How the time to group grows: the ratio of the last to the first against the team's ratio."""
    if len(points) < 2:
        return ""
    (n0, t0), (n1, t1) = points[0], points[-1]
    return (f"From {n0:g} to {n1:g} robots ({n1 / n0:.1f} times as many) the time to group goes from "
            f"{t0:.1f} s to {t1:.1f} s ({t1 / t0:.2f} times).")


def ability(results: Results, figures: Path) -> list[str]:
    lines = ["| chain | allocation | group: B for the task won (its difficulty) | tasks completed |",
             "|---|---|---|---|"]
    first: list[list[tuple[float, float]]] = []
    for r in [r for r in results if r["experiment"] == "ability"]:
        runs = []
        for k, run in enumerate(r["runs"]):
            pts = [(g["B"], g["difficulty"]) for g in run.get("groups", [])]
            runs.append(pts)
            shown = ", ".join(f"{i}: {b:.2f} ({d:g})" for i, (b, d) in enumerate(pts))
            lines.append(f"| {r['x']} | {k + 1} | {shown} | {'yes' if run['completed'] else 'no'} |")
        first = first or runs
    ability_plot(first, figures / "fig8_ability.png", "Figure 8: group ability against task difficulty, "
                 "4 allocations sharing one history (a robot fails in the third)")
    return lines


def help_table(results: Results) -> list[str]:
    lines = ["| robot failing mid-move | failures | task completed | median recovery (s) "
             "| median enclosed (s) | robot-robot collisions |", "|---|---|---|---|---|---|"]
    rows: dict[str, Results] = {"agent": [], "member": []}
    for r in results:
        if r["experiment"] == "help":
            rows["agent" if r["x"] in r.get("agents", []) else "member"].append(r)
    for role, rs in rows.items():
        if rs:
            done = [r for r in rs if r["completed"]]
            lines.append(f"| {role} | {len(rs)} | {len(done)}/{len(rs)} | "
                         f"{seconds(median([r.get('recovery', math.inf) for r in rs]))} | "
                         f"{seconds(median([r['enclosed'] for r in done]))} | "
                         f"{sum(r['collisions'] for r in rs)} |")
    return lines


def beaten(results: Results) -> list[str]:
    """Issue 9's point 5, each claim with the bench's own count."""
    orders = by_x(results, "table1")
    never = [o for o, rs in orders.items() if not any(r["completed"] for r in rs)]
    _, sizes, _ = curve(results, "size", "grouped", "robots")
    helped = [r for r in results if r["experiment"] == "help"]
    runs = [run for r in results for run in r.get("runs", [r])]
    hits = sum(run["collisions"] for run in runs)
    return [
        f"- Priority orders that never finish: {len(never)} of {len(orders)} (paper: 1 of 6)"
        + (f": {', '.join(never)}" if never else "") + ".",
        f"- Time to group against the team: {growth(sizes) or 'not measured'}",
        f"- A single robot failing mid-move: the tasks completed in {sum(r['completed'] for r in helped)} "
        f"of {len(helped)} runs.",
        f"- Robot-robot collisions over all {len(runs)} runs of the bench: {hits}.",
    ]


def write(results: Results, doc: Path, figures: Path, command: str, wall: float, trials: int) -> list[str]:
    """Write the figures and the `tararc_bench` section of `doc`; returns the section's lines."""
    rel = figures.relative_to(doc.parent)
    lines = [f"Command: `{command}` ({trials} trials, {wall / 60:.1f} min wall). Times are simulated "
             "seconds; medians over the trials that completed (the time to group: over those that "
             "grouped); ∞: none did.", "",
             "### Against the paper (issue 9, point 5)", "", *beaten(results), "",
             "### Table 1: priority orders (10 robots, 3 targets)", "", *table1(results), ""]
    for exp, key, label, xlabel, fig, title in (
        ("density", "converge", "density", "relative density of robots (area ratio)", "fig5_density.png",
         "Figure 5: grouped to enclosed against robot density"),
        ("size", "grouped", "robots", "robots (3 targets for every 10)", "fig6_size.png",
         "Figure 6: start to grouped against the number of robots"),
        ("speed", "converge", "speed (m/s)", "robot top speed (m/s)", "fig7_speed.png",
         "Figure 7: grouped to enclosed against robot speed"),
    ):
        rows, points, every = curve(results, exp, key, label)
        ylabel = "time to group (s)" if key == "grouped" else "convergence time (s)"
        curve_plot(points, every, figures / fig, xlabel=xlabel, ylabel=ylabel, title=title,
                   paper=PAPER_SAYS[exp])
        lines += [f"### {title}", "", f"Paper: {PAPER_SAYS[exp]}.", "", *rows, ""]
        if exp == "size":
            lines += [growth(points), ""]
        lines += [f"![{title}]({rel / fig})", ""]
    lines += ["### Figure 8: group ability over 4 successive allocations", "",
              f"Paper: {PAPER_SAYS['ability']}.", "", *ability(results, figures), "",
              f"![Figure 8]({rel / 'fig8_ability.png'})", "",
              "### Help strategies: one robot failing mid-move", "", f"Paper: {PAPER_SAYS['help']}.", "",
              *help_table(results)]
    write_section(doc, "tararc_bench", lines)
    return lines
