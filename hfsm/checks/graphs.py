"""Checks over graphs: recursion, choice cycles, unreachable states, unused outcomes, unguarded loops."""

from __future__ import annotations

from hfsm import digraph
from hfsm.checks.context import CheckContext
from hfsm.checks.timing import guarded, leaves_in_time
from hfsm.graph import Arc, arcs, state_graph
from hfsm.library import MachineFile
from hfsm.model import ChoiceState, state_calls


def _cyclic_components(g: digraph.MultiDiGraph) -> list[set[object]]:
    components = digraph.strongly_connected_components(g)
    return [c for c in components if len(c) > 1 or any(g.has_edge(n, n) for n in c)]


def check_recursion(ctx: CheckContext) -> None:
    g = ctx.calls
    for component in _cyclic_components(g):
        for caller in sorted(str(c) for c in component):
            for callee in sorted(str(c) for c in g.successors(caller) if c in component):
                mf = ctx.machines[caller]
                chain = " -> ".join(_cycle_through(g, caller, callee))
                for state in g.edges[caller, callee]["states"]:
                    for where, do in state_calls(state, mf.model.states[state]):
                        if do == callee:
                            ctx.error(mf, where, "E312", f"'{caller}' calls itself: {chain}")


def _cycle_through(g: digraph.DiGraph, caller: str, callee: str) -> list[str]:
    back = digraph.shortest_path(g, callee, caller) if callee != caller else [caller]
    return [caller, *back]


def check_state_graph(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    g = _graph(ctx, mf)
    choices = g.subgraph(("state", n) for n, s in m.states.items() if isinstance(s, ChoiceState))
    for component in _cyclic_components(choices):
        names = sorted(str(node[1]) for node in component)  # type: ignore[index]
        message = f"choice states {' -> '.join(names)} form a cycle that takes no time"
        ctx.error(mf, ("states", names[0]), "E313", message, key=True)
    initial = ("state", m.initial_state)
    if initial not in g:
        return
    reached = _reached(ctx, mf)
    for name in m.states:
        if ("state", name) not in reached:
            ctx.warn(
                mf,
                ("states", name),
                "W400",
                f"state '{name}' cannot be reached from '{m.initial_state}'",
                key=True,
            )
    for i, outcome in enumerate(m.outcomes):
        timer_reaches = outcome == "timeout" and m.timer is not None
        if g.in_degree(("outcome", outcome)) == 0 and not timer_reaches:
            ctx.warn(mf, ("outcomes", i), "W401", f"outcome '{outcome}' is never reached")
    if not guarded(ctx, mf.name):
        for names in endless_loops(ctx, mf):
            message = (
                f"states {' -> '.join(names)} can loop forever: no timer on '{mf.name}' or above it"
                if len(names) > 1
                else f"state '{names[0]}' can loop forever: no timer on '{mf.name}' or above it"
            )
            ctx.warn(mf, ("states", names[0]), "W402", message, key=True)


def _graph(ctx: CheckContext, mf: MachineFile) -> digraph.MultiDiGraph:
    key = ("graph", mf.name)
    if key not in ctx.memo:
        ctx.memo[key] = state_graph(mf.model, _arcs(ctx, mf))
    return ctx.memo[key]  # type: ignore[return-value]


def _arcs(ctx: CheckContext, mf: MachineFile) -> list[Arc]:
    key = ("arcs", mf.name)
    if key not in ctx.memo:
        ctx.memo[key] = arcs(mf.model, ctx.specs)
    return ctx.memo[key]  # type: ignore[return-value]


def _reached(ctx: CheckContext, mf: MachineFile) -> set[object]:
    key = ("reached", mf.name)
    if key not in ctx.memo:
        g, initial = _graph(ctx, mf), ("state", mf.model.initial_state)
        ctx.memo[key] = digraph.descendants(g, initial) | {initial} if initial in g else set()
    return ctx.memo[key]  # type: ignore[return-value]


def endless_loops(ctx: CheckContext, mf: MachineFile) -> list[list[str]]:
    """Loops of reached states that no timer or watch can leave (docs/REFERENCE.md#watches: those end), in
    file order."""
    key = ("loops", mf.name)
    if key not in ctx.memo:
        m = mf.model
        leaving = leaves_in_time(m, _arcs(ctx, mf))
        loops = []
        for component in _cyclic_components(_ordinary(_graph(ctx, mf), _reached(ctx, mf))):
            names = [n for n in m.states if ("state", n) in component]
            if not any(target not in names for name in names for target in leaving.get(name, ())):
                loops.append(names)
        ctx.memo[key] = loops
    return ctx.memo[key]  # type: ignore[return-value]


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
