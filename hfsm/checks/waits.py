"""Warnings about regions of parallel states, the ways FlexBE's and SMACH's concurrency freezes:
an awaited region that can wait forever with no timer above it (W403), and two regions that
consume the same message, of which only the first in order gets it (W404)."""

from __future__ import annotations

from typing import Any

from hfsm.builtins import REGISTRY
from hfsm.checks.context import CheckContext, parallel_states
from hfsm.checks.graphs import endless_loops
from hfsm.checks.timing import guarded, timed_state
from hfsm.library import MachineFile
from hfsm.model import CallState, ChoiceState, ParallelState


def check_regions(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    for name, state in parallel_states(m):
        bounded = timed_state(m, name) or guarded(ctx, mf.name)
        first: dict[str, str] = {}
        for region_name, region in state.parallel.items():
            at = ("states", name, "parallel", region_name)
            for message in sorted(consumes(ctx, region.do, region.with_)):
                taker = first.setdefault(message, region_name)
                if taker != region_name:
                    text = (
                        f"regions '{taker}' and '{region_name}' both consume message '{message}': "
                        f"'{taker}' takes it first and '{region_name}' may never see it"
                    )
                    ctx.warn(mf, at, "W404", text, key=True)
            why = None if bounded or region.background else blocks(ctx, region.do, region.with_)
            if why:
                text = (
                    f"region '{region_name}' can wait forever ({why}) and nothing above it has a timer; "
                    f"put a timer on '{name}'"
                )
                ctx.warn(mf, at, "W403", text, key=True)


def blocks(ctx: CheckContext, do: str, with_: dict[str, Any]) -> str | None:
    """Why a call can wait without bound (None: it cannot, as far as the checks know)."""
    builtin = REGISTRY.get(do)
    if builtin is not None:
        return builtin.blocks(with_)
    if do in ctx.machines:
        return _machine_blocks(ctx, do)
    return None


def _machine_blocks(ctx: CheckContext, name: str) -> str | None:
    key = ("blocks", name)
    if key in ctx.memo:
        return ctx.memo[key]  # type: ignore[return-value]
    ctx.memo[key] = None  # a machine that calls itself (E312) is not followed twice
    mf = ctx.machines[name]
    why = None if mf.model.timer is not None else _first_block(ctx, mf)
    ctx.memo[key] = why
    return why


def _first_block(ctx: CheckContext, mf: MachineFile) -> str | None:
    m = mf.model
    for state_name, state in m.states.items():
        if isinstance(state, ChoiceState) or timed_state(m, state_name):
            continue
        calls = [(state.do, state.with_)] if isinstance(state, CallState) else _awaited(state)
        for do, with_ in calls:
            why = blocks(ctx, do, with_)
            if why:
                inner = why.startswith(f"{do}/") or why.startswith(f"{do}:")
                return f"{mf.name}/{state_name}/{why}" if inner else f"{mf.name}/{state_name}: {why}"
    loops = endless_loops(ctx, mf)
    return f"{mf.name}: an endless loop through {' -> '.join(loops[0])}" if loops else None


def _awaited(state: ParallelState) -> list[tuple[str, dict[str, Any]]]:
    return [(r.do, r.with_) for r in state.parallel.values() if not r.background]


def consumes(ctx: CheckContext, do: str, with_: dict[str, Any]) -> frozenset[str]:
    """The messages a call takes from the mailbox: by a built-in (`wait_for`), or by an arc, at any depth."""
    builtin = REGISTRY.get(do)
    if builtin is not None:
        return builtin.consumes(with_)
    if do not in ctx.machines:
        return frozenset()
    key = ("consumes", do)
    if key in ctx.memo:
        return ctx.memo[key]  # type: ignore[return-value]
    ctx.memo[key] = frozenset()
    m = ctx.machines[do].model
    found = {e for e in m.any if e in m.receives}
    for state in m.states.values():
        if isinstance(state, ChoiceState):
            continue
        found.update(e for e in state.on if e in m.receives)
        calls = (
            [(state.do, state.with_)]
            if isinstance(state, CallState)
            else [(r.do, r.with_) for r in state.parallel.values()]
        )
        for callee, args in calls:
            found |= consumes(ctx, callee, args)
    result = frozenset(found)
    ctx.memo[key] = result
    return result
