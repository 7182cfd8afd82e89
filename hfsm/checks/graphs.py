"""Checks over graphs: recursion, choice cycles, unreachable states, unused outcomes, unguarded loops."""

from __future__ import annotations

from functools import cache

from hfsm import digraph
from hfsm.checks.context import CheckContext
from hfsm.graph import arcs, state_graph
from hfsm.library import MachineFile
from hfsm.model import CallState, ChoiceState


def _cyclic_components(g: digraph.MultiDiGraph) -> list[set[object]]:
    components = digraph.strongly_connected_components(g)
    return [c for c in components if len(c) > 1 or any(g.has_edge(n, n) for n in c)]


def check_recursion(ctx: CheckContext) -> None:
    g = ctx.calls
    for component in _cyclic_components(g):
        for caller in sorted(str(c) for c in component):
            for callee in sorted(str(c) for c in g.successors(caller) if c in component):
                mf = ctx.machines[caller]
                for state in g.edges[caller, callee]["states"]:
                    chain = " -> ".join(_cycle_through(g, caller, callee))
                    ctx.error(mf, ("states", state, "do"), "E312", f"'{caller}' calls itself: {chain}")


def _cycle_through(g: digraph.DiGraph, caller: str, callee: str) -> list[str]:
    back = digraph.shortest_path(g, callee, caller) if callee != caller else [caller]
    return [caller, *back]


def check_state_graph(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    g = state_graph(m, arcs(m, ctx.specs))
    choices = g.subgraph(("state", n) for n, s in m.states.items() if isinstance(s, ChoiceState))
    for component in _cyclic_components(choices):
        names = sorted(str(node[1]) for node in component)  # type: ignore[index]
        message = f"choice states {' -> '.join(names)} form a cycle that takes no time"
        ctx.error(mf, ("states", names[0]), "E313", message, key=True)
    initial = ("state", m.initial_state)
    if initial not in g:
        return
    reached = digraph.descendants(g, initial) | {initial}
    for name in m.states:
        if ("state", name) not in reached:
            ctx.warn(
                mf, ("states", name), "W400", f"state '{name}' cannot be reached from '{m.initial_state}'"
            )
    for i, outcome in enumerate(m.outcomes):
        timer_reaches = outcome == "timeout" and m.timer is not None
        if g.in_degree(("outcome", outcome)) == 0 and not timer_reaches:
            ctx.warn(mf, ("outcomes", i), "W401", f"outcome '{outcome}' is never reached")
    if not _guarded(ctx, mf.name):
        _warn_loops(ctx, mf, _ordinary(g, reached))


def _ordinary(g: digraph.MultiDiGraph, reached: set[object]) -> digraph.DiGraph:
    """The reached states and their arcs but the common error ones, as a plain graph."""
    out = digraph.DiGraph()
    out.add_nodes_from(reached)
    for u, v, _, d in g.edge_items():
        if u in reached and v in reached and not _common_error(d):
            out.add_edge(u, v)
    return out


def _common_error(edge: dict[str, object]) -> bool:
    """`any: {error: X}` arcs are exceptional paths; zero-time error loops hit the entry limit."""
    return bool(edge["common"]) and edge["kind"] == "error"


def _warn_loops(ctx: CheckContext, mf: MachineFile, g: digraph.DiGraph) -> None:
    for component in _cyclic_components(g):
        names = [n for n in mf.model.states if ("state", n) in component]
        message = (
            f"states {' -> '.join(names)} can loop forever: no timer on '{mf.name}' or above it"
            if len(names) > 1
            else f"state '{names[0]}' can loop forever: no timer on '{mf.name}' or above it"
        )
        ctx.warn(mf, ("states", names[0]), "W402", message)


def _guarded(ctx: CheckContext, name: str) -> bool:
    """A machine's loops are bounded when it, or every path of calls above it, has a timer."""
    g = ctx.calls

    @cache
    def guarded(machine: str, depth: int) -> bool:
        model = ctx.machines[machine].model
        if model.timer is not None:
            return True
        callers = list(g.predecessors(machine))
        if not callers or depth > len(ctx.machines):
            return False
        for caller in callers:
            for state in g.edges[caller, machine]["states"]:
                s = ctx.machines[caller].model.states[state]
                timed = isinstance(s, CallState) and s.timer is not None
                if not timed and not guarded(caller, depth + 1):
                    return False
        return True

    return guarded(name, 0)
