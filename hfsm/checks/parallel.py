"""Checks of parallel states (docs/REFERENCE.md#parallel-states): regions, join rules, a join that cannot
hang, and `on:`."""

from __future__ import annotations

from hfsm.checks.context import CheckContext, parallel_states
from hfsm.checks.coverage import Rule, uncovered
from hfsm.library import MachineFile
from hfsm.model import JoinElse, JoinRule, ParallelState
from hfsm.names import did_you_mean

Where = tuple[str | int, ...]


def check_parallel(ctx: CheckContext, mf: MachineFile) -> None:
    for name, state in parallel_states(mf.model):
        where: Where = ("states", name)
        awaited = [r for r, region in state.parallel.items() if not region.background]
        if not awaited:
            message = f"parallel state '{name}' awaits no region: at least one must not be background"
            ctx.error(mf, (*where, "parallel"), "E324", message, key=True)
        _check_saves(ctx, mf, where, state)
        _check_rules(ctx, mf, where, state)
        _check_join_covers(ctx, mf, where, state, awaited)
        _check_events(ctx, mf, where, state)


def _check_saves(ctx: CheckContext, mf: MachineFile, where: Where, state: ParallelState) -> None:
    saved_by: dict[str, str] = {}
    for region_name, region in state.parallel.items():
        for var in region.save:
            first = saved_by.setdefault(var, region_name)
            if first != region_name:
                message = f"regions '{first}' and '{region_name}' both save into var '{var}'"
                ctx.error(mf, (*where, "parallel", region_name, "save", var), "E325", message, key=True)


def _check_rules(ctx: CheckContext, mf: MachineFile, where: Where, state: ParallelState) -> None:
    last = len(state.join) - 1
    for i, rule in enumerate(state.join):
        if isinstance(rule, JoinElse):
            if i != last:
                ctx.error(mf, (*where, "join", i), "E311", "'else' must be the last rule of 'join'")
            continue
        for region_name, outcomes in rule.when.items():
            at = (*where, "join", i, "when", region_name)
            region = state.parallel.get(region_name)
            if region is None:
                hint = did_you_mean(region_name, state.parallel) or f" (regions: {', '.join(state.parallel)})"
                ctx.error(mf, at, "E321", f"unknown region '{region_name}'{hint}", key=True)
            elif region.background:
                message = f"region '{region_name}' is background: it is never awaited, so no rule may name it"
                ctx.error(mf, at, "E322", message, key=True)
            else:
                _check_outcomes(ctx, mf, at, region.do, outcomes)


def _check_outcomes(
    ctx: CheckContext, mf: MachineFile, at: Where, do: str, outcomes: str | list[str]
) -> None:
    spec = ctx.specs.get(do)
    if spec is None:
        return  # an unknown behaviour is reported at its `do`
    listed = (
        [(at, outcomes)] if isinstance(outcomes, str) else [((*at, j), o) for j, o in enumerate(outcomes)]
    )
    for path, outcome in listed:
        if outcome not in spec.outcomes:
            hint = did_you_mean(outcome, spec.outcomes) or f" (it has: {', '.join(spec.outcomes)})"
            ctx.error(mf, path, "E323", f"'{do}' has no outcome '{outcome}'{hint}")


def _check_join_covers(
    ctx: CheckContext, mf: MachineFile, where: Where, state: ParallelState, awaited: list[str]
) -> None:
    if not awaited or isinstance(state.join[-1], JoinElse):
        return
    specs = [ctx.specs.get(state.parallel[r].do) for r in awaited]
    regions = {r: spec.outcomes for r, spec in zip(awaited, specs, strict=True) if spec is not None}
    if len(regions) != len(awaited):
        return  # an unknown behaviour: its outcomes are not known
    rules: list[Rule] = []
    for rule in state.join:
        if isinstance(rule, JoinRule):
            rules.append(
                {
                    r: frozenset([o] if isinstance(o, str) else o)
                    for r, o in rule.when.items()
                    if r in regions  # a rule naming a wrong region is reported as such, not twice
                }
            )
    gap = uncovered(regions, rules)
    if gap is None:
        return
    more = f" (and {gap.count - 1} more of {gap.total} combinations)" if gap.count > 1 else ""
    message = (
        f"the join can hang: no rule holds when {gap.text()}{more}; "
        "add a rule for it, or end 'join' with 'else'"
    )
    ctx.error(mf, (*where, "join"), "E320", message, key=True)


def _check_events(ctx: CheckContext, mf: MachineFile, where: Where, state: ParallelState) -> None:
    """A parallel state leaves by its rules; its `on:` maps only `timeout`, messages and `error`."""
    receives = set(mf.model.receives)
    for event in state.on:
        at = (*where, "on", event)
        if event == "timeout" and state.timer is None:
            ctx.error(mf, at, "E309", "'timeout' is mapped, but the parallel state has no timer", key=True)
        elif event not in receives and event not in ("timeout", "error"):
            hint = did_you_mean(event, [*receives, "error", "timeout"])
            message = (
                f"'{event}' is not a message in 'receives' nor 'timeout' or 'error': a parallel state "
                f"leaves on its regions' outcomes by its 'join' rules{hint}"
            )
            ctx.error(mf, at, "E303", message, key=True)
    if state.timer is not None and "timeout" not in state.on:
        ctx.error(mf, (*where, "timer"), "E310", "the state has a timer, so 'on' must map 'timeout'")
