"""Checks of each call state against the signature of what it calls (docs/REFERENCE.md#states,
docs/REFERENCE.md#events-and-arcs, docs/REFERENCE.md#built-in-behaviours)."""

from __future__ import annotations

from hfsm.builtins import REGISTRY
from hfsm.checks.context import CheckContext, call_states, parallel_states
from hfsm.checks.forgotten import reads_like_expression, wrapped
from hfsm.expr import ExprSyntaxError
from hfsm.library import MachineFile
from hfsm.model import CallState, Region
from hfsm.names import RESERVED_MESSAGES, did_you_mean, is_name
from hfsm.spec import BehaviourSpec, shown, type_ok
from hfsm.values import split

Where = tuple[str | int, ...]


def _is_expr(value: object) -> bool:
    if not isinstance(value, str):
        return False
    try:
        parts = split(value) if "${" in value else [value]
    except ExprSyntaxError:
        return True  # an unclosed `${`: the expressions check reports it (E314), not its type
    return len(parts) == 1 and isinstance(parts[0], tuple)


def check_calls(ctx: CheckContext, mf: MachineFile) -> None:
    for name, state in call_states(mf.model):
        spec = ctx.specs.get(state.do)
        if spec is None:
            continue  # reported by the library as an unknown behaviour
        where: Where = ("states", name)
        _check_params(ctx, mf, where, state, spec)
        _check_events(ctx, mf, where, state, spec)
        _check_save(ctx, mf, where, state, spec)
        _check_retry(ctx, mf, where, state, spec)
    for name, parallel in parallel_states(mf.model):
        for region_name, region in parallel.parallel.items():
            spec = ctx.specs.get(region.do)
            if spec is not None:
                at: Where = ("states", name, "parallel", region_name)
                _check_params(ctx, mf, at, region, spec)
                _check_save(ctx, mf, at, region, spec)


def _check_params(
    ctx: CheckContext, mf: MachineFile, where: Where, state: CallState | Region, spec: BehaviourSpec
) -> None:
    given = state.with_
    if spec.open_params:
        for key in given:
            if key not in mf.model.vars:
                hint = did_you_mean(key, mf.model.vars)
                ctx.error(mf, (*where, "with", key), "E304", f"unknown variable '{key}'{hint}", key=True)
        return
    for key, value in given.items():
        param = spec.params.get(key)
        if param is None:
            hint = (
                did_you_mean(key, spec.params)
                or f" ('{spec.name}' takes: {', '.join(spec.params) or 'nothing'})"
            )
            ctx.error(
                mf, (*where, "with", key), "E302", f"unknown param '{key}' of '{spec.name}'{hint}", key=True
            )
        elif not _is_expr(value) and not type_ok(value, param.type):
            kind = type(value).__name__
            message = f"param '{key}' of '{spec.name}' takes {param.type}, not {kind} {shown(value)}"
            if isinstance(value, str) and reads_like_expression(value):
                message += f"; write '{wrapped(value)}' for an expression"
            ctx.error(mf, (*where, "with", key), "E306", message)
        elif param.choices and not _is_expr(value) and value not in param.choices:
            values = " or ".join(f"'{c}'" for c in param.choices)
            ctx.error(mf, (*where, "with", key), "E332", f"param '{key}' of '{spec.name}' takes {values}, "
                      f"not {shown(value)}{did_you_mean(str(value), param.choices)}")
    for key, param in spec.params.items():
        if param.required and key not in given:
            ctx.error(mf, (*where, "do"), "E307", f"'{spec.name}' needs param '{key}'")
    _check_message_name(ctx, mf, where, state, spec)


def _check_message_name(
    ctx: CheckContext, mf: MachineFile, where: Where, state: CallState | Region, spec: BehaviourSpec
) -> None:
    builtin = REGISTRY.get(spec.name) if spec.kind == "builtin" else None
    param = builtin.message_param if builtin is not None else ""
    message = state.with_.get(param) if param else None
    if not isinstance(message, str) or _is_expr(message):
        return
    if not is_name(message):
        ctx.error(mf, (*where, "with", param), "E201", f"bad message name '{message}'")
    elif message in RESERVED_MESSAGES:
        ctx.error(mf, (*where, "with", param), "E202", f"message name '{message}' is reserved")


def _check_events(
    ctx: CheckContext, mf: MachineFile, where: Where, state: CallState, spec: BehaviourSpec
) -> None:
    receives = set(mf.model.receives)
    outcomes = set(spec.outcomes)
    timed = state.timer is not None or "timeout" in outcomes
    for event in state.on:
        at = (*where, "on", event)
        if event in outcomes and event in receives:
            message = f"'{event}' is both an outcome of '{spec.name}' and a message in 'receives' (ambiguous)"
            ctx.error(mf, at, "E317", message, key=True)
        elif event == "timeout" and not timed:
            message = (
                f"'timeout' is mapped, but the state has no timer and '{spec.name}' has no outcome 'timeout'"
            )
            ctx.error(mf, at, "E309", message, key=True)
        elif event not in outcomes and event not in receives and event not in ("timeout", "error"):
            hint = did_you_mean(event, [*outcomes, *receives, "error"])
            known = ", ".join(spec.outcomes)
            message = (
                f"'{event}' is neither an outcome of '{spec.name}' ({known})"
                f" nor a message in 'receives'{hint}"
            )
            ctx.error(mf, at, "E303", message, key=True)
    retried = set(state.retry.on) if state.retry else set()
    for outcome in spec.outcomes:
        if outcome not in state.on and outcome not in retried:
            ctx.error(
                mf, (*where, "do"), "E308", f"outcome '{outcome}' of '{spec.name}' is not mapped in 'on'"
            )
        if outcome in mf.model.any:
            message = f"outcome '{outcome}' of '{spec.name}' is also a message mapped in 'any' (ambiguous)"
            ctx.error(mf, (*where, "do"), "E317", message)
    if state.timer is not None and "timeout" not in state.on:
        ctx.error(mf, (*where, "timer"), "E310", "the state has a timer, so 'on' must map 'timeout'")


def _check_save(
    ctx: CheckContext, mf: MachineFile, where: Where, state: CallState | Region, spec: BehaviourSpec
) -> None:
    for var, output in state.save.items():
        if var not in mf.model.vars:
            hint = did_you_mean(var, mf.model.vars)
            ctx.error(mf, (*where, "save", var), "E304", f"unknown variable '{var}'{hint}", key=True)
        if spec.outputs is not None and output not in spec.outputs:
            declared = ", ".join(sorted(spec.outputs)) or "none"
            hint = did_you_mean(output, spec.outputs) or f" (outputs: {declared})"
            ctx.error(mf, (*where, "save", var), "E305", f"'{spec.name}' has no output '{output}'{hint}")


def _check_retry(
    ctx: CheckContext, mf: MachineFile, where: Where, state: CallState, spec: BehaviourSpec
) -> None:
    """Every outcome retried is one the callee has, and is still mapped for after the last retry."""
    if state.retry is None:
        return
    for i, outcome in enumerate(state.retry.on):
        at = (*where, "retry", "on", i)
        if outcome == "error":
            continue
        if outcome not in spec.outcomes:
            known = ", ".join(spec.outcomes)
            hint = did_you_mean(outcome, [*spec.outcomes, "error"]) or f" (it has: {known}, and 'error')"
            tail = "; a state's own timer is never retried" if outcome == "timeout" else ""
            ctx.error(mf, at, "E327", f"'{spec.name}' has no outcome '{outcome}' to retry{hint}{tail}")
        elif outcome not in state.on:
            message = f"retried outcome '{outcome}' must still be mapped in 'on' (taken after the last retry)"
            ctx.error(mf, at, "E328", message)
