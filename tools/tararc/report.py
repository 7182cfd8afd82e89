"""The bench's results as Markdown tables beside the paper's, and its figures, in docs/TARARC.md."""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from tools.docsection import write_section
from tools.tararc.ability import chain
from tools.tararc.experiments import PAPER_SAYS, PAPER_TABLE1_PRINTED
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
    for order, paper in PAPER_TABLE1_PRINTED.items():
        rs = by_x(results, "table1").get(str(list(order)), [])
        if rs:
            lines.append(f"| {order} | {paper} | {_row(rs, 'converge')} |")
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


def _cell(g: dict[str, Any]) -> str:
    return f"{g['B']:.2f} (F {g['F']:.2f}) → {g['difficulty']:g}" + ("" if g["ok"] else ", **failed**")


def ability(results: Results, figures: Path) -> list[str]:
    """Figure 8: each chain's allocations, groups named as the paper's, and the paper's three claims
    counted over the chains."""
    chains = [chain(r["runs"]) for r in results if r["experiment"] == "ability"]
    names = sorted({n for c in chains for alloc in c for n in alloc})
    head = " | ".join(f"group {n}: B (F) → difficulty won" for n in names)
    lines = [f"| chain | allocation | {head} |", "|---|---|" + "---|" * len(names)]
    for k, c in enumerate(chains):
        for a, alloc in enumerate(c):
            cells = " | ".join(_cell(alloc[n]) if n in alloc else "" for n in names)
            lines.append(f"| {k} | {a + 1} | {cells} |")
    if chains:
        ability_plot(chains[0], figures / "fig8_ability.png",
                     "Figure 8: 4 allocations sharing one history; group 0 fails in the third")
    return [*lines, "", *_ability_claims(chains)]


def _ability_claims(chains: list[list[dict[int, dict[str, Any]]]]) -> list[str]:
    allocs = [alloc for c in chains for alloc in c]
    if not allocs:
        return []
    hardest = [max(g["difficulty"] for g in alloc.values()) for alloc in allocs]
    top = sum(2 in alloc and alloc[2]["difficulty"] == h for alloc, h in zip(allocs, hardest, strict=True))
    lines = ["| paper (Figure 8's text) | ours |", "|---|---|",
             f"| group 2 always the most able, always gets the hardest task (0.9) | group 2 won the hardest "
             f"task in {top} of {len(allocs)} allocations |"]
    drops = []
    for c in chains:
        if len(c) >= 4 and 0 in c[2] and 0 in c[3]:
            before, after = c[2][0], c[3][0]
            easiest = after["difficulty"] == min(g["difficulty"] for g in c[3].values())
            drops.append(f"B {before['B']:.2f} → {after['B']:.2f}, F {before['F']:.2f} → {after['F']:.2f}, "
                         f"task {before['difficulty']:g} → {after['difficulty']:g}"
                         + (" (the easiest)" if easiest else ""))
    if drops:
        lines.append("| group 0 fails its third task; its ability drops and in the fourth it gets the "
                     f"easiest | allocation 3 → 4 ({len(drops)} of {len(chains)} chains): "
                     f"{'; '.join(dict.fromkeys(drops))} |")
    ones = [" → ".join(f"{alloc[1]['B']:.2f}" for alloc in c if 1 in alloc) for c in chains]
    second = sum(1 in alloc and sorted(g["difficulty"] for g in alloc.values())[-2] == alloc[1]["difficulty"]
                 for alloc in allocs)
    lines.append("| group 1's ability keeps increasing; it sometimes gets the second hardest task "
                 f"| group 1's B: {'; '.join(dict.fromkeys(ones))}; the second hardest in {second} of "
                 f"{len(allocs)} allocations |")
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


def write(results: Results, doc: Path, figures: Path, command: str, wall: float, trials: int,
          reruns: Sequence[dict[str, Any]] = ()) -> list[str]:
    """Write the figures and the `tararc_bench` section of `doc`; returns the section's lines.
    `reruns`: the experiments run again since (`--only`), each `{command, trials, wall}`."""
    rel = figures.relative_to(doc.parent)
    again = "".join(f" Rerun since: `{r['command']}` ({r['trials']} trials, {r['wall']:.0f} s wall)."
                    for r in reruns)
    lines = [f"Command: `{command}` ({trials} trials, {wall / 60:.1f} min wall).{again} Times are simulated "
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
