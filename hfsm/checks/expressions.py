"""Every expression of a machine compiles, and reads only names that exist where it stands
(docs/REFERENCE.md#expressions, docs/REFERENCE.md#watches)."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from hfsm.checks.context import CheckContext, call_states, choice_states, parallel_states
from hfsm.expr import ExprSyntaxError, Names, compile_expr, reads_at
from hfsm.library import MachineFile
from hfsm.model import IfBranch, Watch
from hfsm.names import did_you_mean
from hfsm.spec import shown, type_ok
from hfsm.values import split

Where = tuple[str | int, ...]


@dataclass(frozen=True)
class Place:
    """What an expression may read where it stands: `vars`, `state.*`, `machine.time`, `in.x`."""

    what: str  # where it stands, for messages: "the machine's timer"
    vars: bool = True
    state: bool = True
    machine_time: bool = True
    inputs: bool = True


IN_STATE = Place("a state")
OUTPUTS = Place("the machine's outputs", state=False)
MACHINE_TIMER = Place("the machine's timer", vars=False, state=False, machine_time=False, inputs=False)
RETRY = Place("a retry's 'times' or 'delay'", vars=False, state=False, machine_time=False, inputs=False)
STATE_NAMES = "only in a state's with, timer and watch, the machine's watch, and a choice's if"


def check_expression(
    ctx: CheckContext, mf: MachineFile, where: Where, source: str, place: Place, offset: int = 0
) -> None:
    """One bare expression, standing at `offset` in the string at `where`: its syntax and names
    (E314, at the characters at fault), then what it reads live (E330, E331)."""
    m = mf.model
    problem = _compile_problem(source, tuple(m.params), tuple(m.vars) if place.vars else None)
    if problem is not None:
        ctx.error(mf, where, "E314", str(problem), span=_span(problem, offset))
        return
    if "state" not in source and "machine" not in source and "in" not in source:
        return  # reads nothing live: no need to parse it again
    reported = set()
    for name, start, end in _reads_at(source):
        if name in reported:
            continue
        reported.add(name)
        root, attr = name.split(".", 1)
        span = (offset + start, offset + end)
        if root == "state" and not place.state:
            ctx.error(mf, where, "E331", f"'{name}' cannot be read in {place.what}; {STATE_NAMES}", span=span)
        elif name == "machine.time" and not place.machine_time:
            ctx.error(mf, where, "E331", f"'machine.time' cannot be read in {place.what}", span=span)
        elif root == "in" and not place.inputs:
            message = f"'in.{attr}' cannot be read in {place.what}; only params and agent.id"
            ctx.error(mf, where, "E331", message, span=span)
        elif root == "in" and ctx.inputs is not None and attr not in ctx.inputs:
            declared = ", ".join(sorted(ctx.inputs)) or "none"
            hint = did_you_mean(attr, ctx.inputs)
            message = f"the run's world declares no input 'in.{attr}' (it declares: {declared}){hint}"
            ctx.error(mf, where, "E330", message, span=span)


@lru_cache(maxsize=8192)
def _compile_problem(
    source: str, params: tuple[str, ...], vars: tuple[str, ...] | None
) -> ExprSyntaxError | None:
    """Why the expression does not compile with these names (None: it does). Kept: an editor's
    server checks the same expressions again on every change."""
    try:
        compile_expr(source, Names(params, vars))
    except ExprSyntaxError as exc:
        return exc
    return None


@lru_cache(maxsize=8192)
def _reads_at(source: str) -> tuple[tuple[str, int, int], ...]:
    return tuple(reads_at(source))


def strings_in(where: Where, value: Any) -> Iterator[tuple[Where, str]]:
    """The strings of a literal tree with where each stands, at any depth, never keys."""
    if isinstance(value, str):
        yield where, value
    elif isinstance(value, dict):
        for key, item in value.items():
            yield from strings_in((*where, key), item)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            yield from strings_in((*where, i), item)


def _span(exc: ExprSyntaxError, offset: int) -> tuple[int, int] | None:
    if exc.start is None:
        return None
    return offset + exc.start, offset + (exc.end if exc.end is not None else exc.start)


def check_value(ctx: CheckContext, mf: MachineFile, where: Where, value: Any, place: Place) -> None:
    """Every `${…}` of a literal tree, at any depth, never in keys; an unclosed one at its `${`."""
    for at, text in strings_in(where, value):
        if "${" not in text:
            continue
        try:
            parts = split(text)
        except ExprSyntaxError as exc:
            ctx.error(mf, at, "E314", str(exc), span=_span(exc, 0))
            continue
        for part in parts:
            if isinstance(part, tuple):
                check_expression(ctx, mf, at, part[0], place, part[1])


def _watches(ctx: CheckContext, mf: MachineFile, where: Where, watches: list[Watch]) -> None:
    for i, watch in enumerate(watches):
        check_expression(ctx, mf, (*where, i, "if"), watch.condition, IN_STATE)


def check_expressions(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    check_value(ctx, mf, ("timer",), m.timer, MACHINE_TIMER)
    for name, expr in m.outputs.items():
        check_value(ctx, mf, ("outputs", name), expr, OUTPUTS)
    _watches(ctx, mf, ("watch",), m.watch)
    for name, state in call_states(m):
        check_value(ctx, mf, ("states", name, "timer"), state.timer, IN_STATE)
        for key, value in state.with_.items():
            check_value(ctx, mf, ("states", name, "with", key), value, IN_STATE)
        _watches(ctx, mf, ("states", name, "watch"), state.watch)
        if state.retry is not None:
            check_value(ctx, mf, ("states", name, "retry", "times"), state.retry.times, RETRY)
            check_value(ctx, mf, ("states", name, "retry", "delay"), state.retry.delay, RETRY)
    for name, parallel in parallel_states(m):
        check_value(ctx, mf, ("states", name, "timer"), parallel.timer, IN_STATE)
        _watches(ctx, mf, ("states", name, "watch"), parallel.watch)
        for region_name, region in parallel.parallel.items():
            for key, value in region.with_.items():
                check_value(ctx, mf, ("states", name, "parallel", region_name, "with", key), value, IN_STATE)
    for name, choice in choice_states(m):
        for i, branch in enumerate(choice.choose):
            if isinstance(branch, IfBranch):
                check_expression(ctx, mf, ("states", name, "choose", i, "if"), branch.condition, IN_STATE)


def check_param_defaults(ctx: CheckContext, mf: MachineFile) -> None:
    for name, param in mf.model.params.items():
        if not param.required and not type_ok(param.default, param.type):
            message = f"default {shown(param.default)} of param '{name}' is not a {param.type}"
            ctx.error(mf, ("params", name, "default"), "E306", message)
