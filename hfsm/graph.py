"""A machine's arcs as plain values, and as networkx graphs for the checks and the diagrams."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import networkx as nx

from hfsm.model import (
    CallState,
    ChoiceState,
    IfBranch,
    JoinElse,
    JoinRule,
    Machine,
    ParallelState,
    state_calls,
)
from hfsm.spec import BehaviourSpec

ArcKind = Literal["outcome", "failure", "timeout", "message", "error", "choice", "else"]
ANY = "*"


@dataclass(frozen=True)
class Arc:
    source: str  # a state, or ANY for the machine's `any:` arcs
    target: str  # a state or an outcome of the machine
    event: str  # the event's name; for a choice branch, its condition
    kind: ArcKind
    order: int = 0  # a choice branch's position, from 1


def arcs(m: Machine, specs: Mapping[str, BehaviourSpec]) -> list[Arc]:
    """Every arc of a machine, in file order, each with the kind of event that takes it."""
    out = [
        Arc(ANY, target, event, "error" if event == "error" else "message") for event, target in m.any.items()
    ]
    out += [Arc(ANY, w.then, w.condition, "choice", i) for i, w in enumerate(m.watch, start=1)]
    receives = set(m.receives)
    for name, state in m.states.items():
        if isinstance(state, CallState | ParallelState):
            spec = specs.get(state.do) if isinstance(state, CallState) else None
            failures = spec.failures if spec else frozenset()
            for event, target in state.on.items():
                out.append(Arc(name, target, event, _kind(event, failures, receives)))
            out += [Arc(name, w.then, w.condition, "choice", i) for i, w in enumerate(state.watch, start=1)]
            if isinstance(state, ParallelState):
                out += [_join_arc(name, rule, i) for i, rule in enumerate(state.join, start=1)]
        elif isinstance(state, ChoiceState):
            for i, branch in enumerate(state.choose, start=1):
                if isinstance(branch, IfBranch):
                    out.append(Arc(name, branch.then, branch.condition, "choice", i))
                else:
                    out.append(Arc(name, branch.else_, "else", "else", i))
    return out


def _join_arc(state: str, rule: JoinRule | JoinElse, order: int) -> Arc:
    if isinstance(rule, JoinElse):
        return Arc(state, rule.else_, "else", "else", order)
    when = ", ".join(f"{r}={'|'.join(o) if isinstance(o, list) else o}" for r, o in rule.when.items())
    return Arc(state, rule.then, when, "choice", order)


def _kind(event: str, failures: frozenset[str], receives: set[str]) -> ArcKind:
    if event == "timeout":
        return "timeout"
    if event == "error":
        return "error"
    if event in failures:
        return "failure"
    return "message" if event in receives else "outcome"


def state_graph(m: Machine, machine_arcs: list[Arc]) -> nx.MultiDiGraph:
    """Nodes ('state', name) and ('outcome', name); `any:` arcs drawn from every state."""
    g = nx.MultiDiGraph()
    g.add_nodes_from((("state", s) for s in m.states), role="state")
    g.add_nodes_from((("outcome", o) for o in m.all_outcomes), role="outcome")
    for arc in machine_arcs:
        target = ("state", arc.target) if arc.target in m.states else ("outcome", arc.target)
        if target not in g:
            continue
        sources = m.states if arc.source == ANY else [arc.source]
        for source in sources:
            if arc.source == ANY and arc.kind != "error" and isinstance(m.states[source], ChoiceState):
                continue  # in a choice state only `error` can fire
            g.add_edge(("state", source), target, event=arc.event, kind=arc.kind, common=arc.source == ANY)
    return g


def call_graph(machines: Mapping[str, Machine]) -> nx.DiGraph:
    """Machines and what they call; edge attribute `states` lists the calling states."""
    g = nx.DiGraph()
    for name, m in machines.items():
        g.add_node(name)
        for state_name, state in m.states.items():
            for _, do in state_calls(state_name, state):
                if g.has_edge(name, do):
                    g.edges[name, do]["states"].append(state_name)
                else:
                    g.add_edge(name, do, states=[state_name])
    return g
