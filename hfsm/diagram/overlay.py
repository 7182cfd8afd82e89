"""A run drawn over a figure: visits and time per state, how often each arc was taken, where agents ended.

A trace record's path is [top machine, state at depth 0, state at depth 1, …]. The machine at each
depth is found from the `do` of the state above it, so every record is counted once for each machine
it lies in, under the path relative to that machine: the figure of `lift` shows all runs of `lift`,
however deep they were called, and a figure drawn with --depth finds its inline states too.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

from hfsm.diagram import text
from hfsm.diagram.extract import TIMER
from hfsm.diagram.model import Cluster, Edge, Emphasis, Figure, Item, Ref
from hfsm.diagram.text import TIMES
from hfsm.graph import ANY, WATCH
from hfsm.model import CallState, Machine, ParallelState

Key = tuple[str, Ref]  # (machine, path relative to it)
_STATE_ROLES = ("machine", "primitive", "builtin", "choice", "parallel", "barrier")


@dataclass
class Stats:
    visits: Counter[Key] = field(default_factory=Counter)
    seconds: defaultdict[Key, float] = field(default_factory=lambda: defaultdict(float))
    arcs: Counter[tuple[str, Ref, str]] = field(default_factory=Counter)
    ended: defaultdict[Key, list[str]] = field(default_factory=lambda: defaultdict(list))
    summary: list[str] = field(default_factory=list)


def collect(records: Iterable[Mapping[str, Any]], machines: Mapping[str, Machine]) -> Stats:
    """Count a trace's records for every machine each lies in."""
    stats = Stats()
    opened: dict[tuple[str, tuple[str, ...]], float] = {}
    last: dict[str, Mapping[str, Any]] = {}
    entered: dict[str, list[str]] = {}
    for r in records:
        agent, path, kind = str(r.get("agent", "")), [str(p) for p in r.get("path", [])], r.get("kind")
        if not path:
            continue
        views = _views(path, machines)
        last[agent] = r
        if kind == "enter":
            entered[agent] = path
            opened[(agent, tuple(path))] = float(r.get("t", 0))
            for key in views:
                stats.visits[key] += 1 if key[1] else 0
        elif kind == "exit":
            began = opened.pop((agent, tuple(path)), None)
            for key in views:
                if began is not None and key[1]:
                    stats.seconds[key] += float(r.get("t", 0)) - began
        elif kind == "event":
            _event(stats, r, path, views, machines)
        elif kind == "timeout" and r.get("timer") == "machine":
            for m, rel in views:
                stats.arcs[(m, (*rel, TIMER), "timeout")] += 1
    for agent, r in last.items():
        _ended(stats, agent, r, entered.get(agent, []), machines)
    return stats


def _views(path: list[str], machines: Mapping[str, Machine]) -> list[Key]:
    """(machine, path relative to it) for each machine on the path, outermost first.

    Below a parallel state the next element is a region's name, whose `do` is the next machine.
    """
    out: list[Key] = []
    name, i = path[0], 0
    while i < len(path):
        machine = machines.get(name)
        if machine is None:
            break
        out.append((name, tuple(path[i + 1 :])))
        state = machine.states.get(path[i + 1]) if i + 1 < len(path) else None
        if isinstance(state, ParallelState):
            region = state.parallel.get(path[i + 2]) if i + 2 < len(path) else None
            name, i = (region.do if region else ""), i + 2
        else:
            name, i = (state.do if isinstance(state, CallState) else ""), i + 1
    return out


def _event(
    stats: Stats, r: Mapping[str, Any], path: list[str], views: list[Key], machines: Mapping[str, Machine]
) -> None:
    event, target = str(r.get("event", "")), str(r.get("target"))
    holder = next((m for m, rel in reversed(views) if len(rel) == 1), "")  # whose state took the arc
    owner = machines.get(holder)
    into_outcome = owner is not None and target in owner.all_outcomes
    for m, rel in views:
        if rel:
            stats.arcs[(m, rel, event)] += 1
            if into_outcome:
                stats.visits[(m, (*rel[:-1], target))] += 1


def _ended(
    stats: Stats, agent: str, r: Mapping[str, Any], entered: list[str], machines: Mapping[str, Machine]
) -> None:
    t = text.number(round(float(r.get("t", 0)), 3))
    outcome = r.get("outcome") if r.get("kind") == "exit" and len(r.get("path", [])) == 1 else None
    if outcome is not None:
        stats.ended[(str(r["path"][0]), (str(outcome),))].append(agent)
        stats.summary.append(f"{agent}: ended in '{outcome}' at t = {t} s")
        return
    for m, rel in _views(entered, machines) if entered else []:
        for n in range(1, len(rel) + 1):  # the state, and the states that called it
            stats.ended[(m, rel[:n])].append(agent)
    where = "/".join(entered) or "?"
    stats.summary.append(f"{agent}: did not end; last in {where} at t = {t} s")


def apply(figure: Figure, machine: str, stats: Stats) -> Figure:
    """The figure with the run drawn over it: counts on states and arcs, unvisited parts faded."""
    items = tuple(_item(i, machine, stats) for i in figure.items)
    claimed = {(e.ref, ev) for e in figure.edges if e.ref for ev in e.events}
    edges = tuple(_edge(e, machine, stats, claimed) for e in figure.edges)
    return replace(figure, items=items, edges=edges, notes=(*figure.notes, *stats.summary))


def _item(item: Item, machine: str, stats: Stats) -> Item:
    if isinstance(item, Cluster):
        inner = tuple(_item(i, machine, stats) for i in item.items)
        lines, emphasis, ended = _marks(item.ref, "machine", machine, stats)
        return replace(item, items=inner, stats=lines + _end(ended), emphasis=emphasis)
    lines, emphasis, ended = _marks(item.ref, item.role, machine, stats)
    if item.role not in (*_STATE_ROLES, "success", "failure"):
        return item
    lanes = tuple(
        replace(lane, stats=m[0], emphasis=m[1])
        for lane in item.lanes
        for m in [_marks(lane.ref, "machine", machine, stats)]
    )
    return replace(item, stats=lines + _end(ended), emphasis=emphasis, lanes=lanes)


def _end(ended: list[str]) -> tuple[str, ...]:
    """Where agents ended, as a line in the node (an xlabel could overlap its neighbours)."""
    return (f"end: {', '.join(ended)}",) if ended else ()


def _marks(
    ref: Ref | None, role: str, machine: str, stats: Stats
) -> tuple[tuple[str, ...], Emphasis, list[str]]:
    if ref is None:
        return (), "normal", []
    key = (machine, ref)
    visits = stats.visits.get(key, 0)
    ended = stats.ended.get(key, [])
    emphasis: Emphasis = "ended" if ended else "normal" if visits else "faded"
    if not visits:
        return (), emphasis, ended
    if role in ("success", "failure"):
        return (f"{TIMES}{visits}",), emphasis, ended
    seconds = stats.seconds.get(key, 0.0)
    timed = f", {text.number(round(seconds, 2))} s" if role != "choice" else ""
    return (f"{TIMES}{visits}{timed}",), emphasis, ended


def _edge(e: Edge, machine: str, stats: Stats, claimed: set[tuple[Ref, str]]) -> Edge:
    if e.ref is None or e.style in ("start", "invisible"):
        return e
    count = sum(stats.arcs.get((machine, e.ref, ev), 0) for ev in e.events)
    if e.ref[-1:] in ((ANY,), (WATCH,)):
        count += sum(
            n
            for (m, rel, ev), n in stats.arcs.items()
            if m == machine and ev in e.events and (rel, ev) not in claimed and _sibling(rel, e.ref)
        )
    return replace(e, count=count or None, emphasis="normal" if count else "faded")


def _sibling(rel: Ref, any_ref: Ref) -> bool:
    """Whether a state's path lies in the machine whose `any:` arcs (or watches) have this path."""
    return len(rel) == len(any_ref) and rel[:-1] == any_ref[:-1]
