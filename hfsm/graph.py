"""A machine's arcs as plain values, and as small graphs (hfsm.digraph) for the checks and the diagrams."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

from hfsm import digraph
from hfsm.model import CallState, ChoiceState, IfBranch, JoinRule, Machine, Watch, state_calls
from hfsm.spec import BehaviourSpec

ArcKind = Literal[
    "outcome", "failure", "timeout", "message", "error", "choice", "else", "join", "watch", "retry"
]
ANY = "*"
WATCH = "^"  # the source of the machine's own watches, tried in every call and parallel state


@dataclass(frozen=True)
class Arc:
    source: str  # a state, or ANY for the machine's `any:` arcs
    target: str  # a state or an outcome of the machine
    event: str  # the event's name; for a choice branch or a watch, its condition; a join rule's text
    kind: ArcKind
    order: int = 0  # a choice branch's, join rule's or watch's position, from 1


def arcs(m: Machine, specs: Mapping[str, BehaviourSpec]) -> list[Arc]:
    """Every arc of a machine, in file order, each with the kind of event that takes it.

    A parallel state's join rules are arcs of kind `join` (its `else` of kind `else`); a watch is an
    arc of kind `watch`; a retry is one arc of kind `retry` back to its state per outcome retried.
    """
    out = [
        Arc(ANY, target, event, "error" if event == "error" else "message") for event, target in m.any.items()
    ]
    out += _watches(WATCH, m.watch)
    receives = set(m.receives)
    for name, state in m.states.items():
        if isinstance(state, CallState):
            spec = specs.get(state.do)
            failures = spec.failures if spec else frozenset()
            for event, target in state.on.items():
                out.append(Arc(name, target, event, _kind(event, failures, receives)))
            out += _watches(name, state.watch)
            out += [Arc(name, name, event, "retry") for event in state.retry.on] if state.retry else []
        elif isinstance(state, ChoiceState):
            for i, branch in enumerate(state.choose, start=1):
                if isinstance(branch, IfBranch):
                    out.append(Arc(name, branch.then, branch.condition, "choice", i))
                else:
                    out.append(Arc(name, branch.else_, "else", "else", i))
        else:
            out += [
                Arc(name, target, event, _kind(event, frozenset(), receives))
                for event, target in state.on.items()
            ]
            for i, rule in enumerate(state.join, start=1):
                if isinstance(rule, JoinRule):
                    out.append(Arc(name, rule.then, join_text(rule), "join", i))
                else:
                    out.append(Arc(name, rule.else_, "else", "else", i))
            out += _watches(name, state.watch)
    return out


def join_text(rule: JoinRule) -> str:
    """`explore=finished|failed, detect=found`: the rule as the trace names its event."""
    return ", ".join(f"{r}={'|'.join(o) if isinstance(o, list) else o}" for r, o in rule.when.items())


def _watches(source: str, watches: list[Watch]) -> list[Arc]:
    return [Arc(source, w.then, w.condition, "watch", i) for i, w in enumerate(watches, start=1)]


def _kind(event: str, failures: frozenset[str], receives: set[str]) -> ArcKind:
    if event == "timeout":
        return "timeout"
    if event == "error":
        return "error"
    if event in failures:
        return "failure"
    return "message" if event in receives else "outcome"


def state_graph(m: Machine, machine_arcs: list[Arc]) -> digraph.MultiDiGraph:
    """Nodes ('state', name) and ('outcome', name); `any:` arcs drawn from every state."""
    g = digraph.MultiDiGraph()
    g.add_nodes_from((("state", s) for s in m.states), role="state")
    g.add_nodes_from((("outcome", o) for o in m.all_outcomes), role="outcome")
    for arc in machine_arcs:
        target = ("state", arc.target) if arc.target in m.states else ("outcome", arc.target)
        if target not in g or arc.kind == "retry" or (arc.kind == "watch" and arc.target == arc.source):
            continue  # a retry, and a watch back to its own state, stay in the state
        sources = m.states if arc.source in (ANY, WATCH) else [arc.source]
        for source in sources:
            if (
                arc.source in (ANY, WATCH)
                and arc.kind != "error"
                and isinstance(m.states[source], ChoiceState)
            ):
                continue  # in a choice state only `error` can fire, and no watch is tried
            if arc.source == WATCH and source == arc.target:
                continue
            common = arc.source in (ANY, WATCH)
            g.add_edge(("state", source), target, event=arc.event, kind=arc.kind, common=common)
    return g


def call_graph(machines: Mapping[str, Machine]) -> digraph.DiGraph:
    """Machines and what they call (a parallel state calls its regions' behaviours); edge attribute
    `states` lists the calling states."""
    g = digraph.DiGraph()
    for name, m in machines.items():
        g.add_node(name)
        for state_name, state in m.states.items():
            for _, do in state_calls(state_name, state):
                if g.has_edge(name, do):
                    g.edges[name, do]["states"].append(state_name)
                else:
                    g.add_edge(name, do, states=[state_name])
    return g
