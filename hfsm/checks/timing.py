"""What bounds time in a machine: timers, and watches that read the time (docs/REFERENCE.md#time-and-timers,
docs/REFERENCE.md#watches)."""

from __future__ import annotations

from hfsm.checks.context import CheckContext
from hfsm.expr import TIMED, reads
from hfsm.graph import ANY, WATCH, Arc
from hfsm.model import ChoiceState, Machine, Watch


def reads_time(watch: Watch) -> bool:
    return bool(reads(watch.condition) & TIMED)


def timed_state(m: Machine, name: str) -> bool:
    """A state that ends in bounded time whatever it calls: a timer, or a watch on the time that
    leaves it (its own or the machine's)."""
    state = m.states[name]
    if isinstance(state, ChoiceState):
        return False
    if state.timer is not None:
        return True
    return any(reads_time(w) and w.then != name for w in [*m.watch, *state.watch])


def leaves_in_time(m: Machine, machine_arcs: list[Arc]) -> dict[str, set[str]]:
    """For each state, the targets of the arcs a timer or a watch can take out of it."""
    out: dict[str, set[str]] = {}
    for arc in machine_arcs:
        if arc.kind not in ("timeout", "watch"):
            continue
        sources = m.states if arc.source in (ANY, WATCH) else [arc.source]
        for source in sources:
            if not isinstance(m.states[source], ChoiceState) and source != arc.target:
                out.setdefault(source, set()).add(arc.target)
    return out


def guarded(ctx: CheckContext, name: str) -> bool:
    """A machine's time is bounded when it, or every chain of calls above it, has a timer."""
    key = ("guarded", name)
    if key not in ctx.memo:
        ctx.memo[key] = _guarded(ctx, name, set())
    return bool(ctx.memo[key])


def _guarded(ctx: CheckContext, machine: str, seen: set[str]) -> bool:
    model = ctx.machines[machine].model
    if model.timer is not None:
        return True
    callers = list(ctx.calls.predecessors(machine))
    if not callers or machine in seen:
        return False
    for caller in callers:
        for state in ctx.calls.edges[caller, machine]["states"]:
            if not timed_state(ctx.machines[caller].model, state) and not _guarded(
                ctx, caller, seen | {machine}
            ):
                return False
    return True
