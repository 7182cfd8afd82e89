"""`autonomy:` on call and parallel states: each key an event the state maps, each value a level."""

from __future__ import annotations

from hfsm.autonomy import LEVELS, join_key
from hfsm.checks.context import CheckContext
from hfsm.library import MachineFile
from hfsm.model import CallState, JoinRule, Machine, ParallelState
from hfsm.names import did_you_mean


def state_events(m: Machine, state: CallState | ParallelState) -> list[str]:
    """The events whose arcs a state's `autonomy:` may name: its `on:`, its machine's `any:`, and
    for a parallel state its join rules by their targets (`join:TARGET`)."""
    events = [*state.on, *(e for e in m.any if e not in state.on)]
    if isinstance(state, ParallelState):
        for rule in state.join:
            key = join_key(rule.then if isinstance(rule, JoinRule) else rule.else_)
            if key not in events:
                events.append(key)
    return events


def check_autonomy(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    for name, state in m.states.items():
        if not isinstance(state, CallState | ParallelState) or not state.autonomy:
            continue
        events = state_events(m, state)
        for event, level in state.autonomy.items():
            path = ("states", name, "autonomy", event)
            if event not in events:
                where = (
                    "its `on:` map, its machine's `any:` or its join (`join:TARGET`)"
                    if isinstance(state, ParallelState)
                    else "its `on:` map or its machine's `any:`"
                )
                message = (
                    f"autonomy names '{event}', which is not an event of state '{name}' "
                    f"({where}){did_you_mean(event, events)}"
                )
                ctx.error(mf, path, "E355", message, key=True)
            if level not in LEVELS:
                message = (
                    f"autonomy level '{level}' is not one of {', '.join(LEVELS)}"
                    f"{did_you_mean(str(level), LEVELS)}"
                )
                ctx.error(mf, path, "E356", message)
