"""Every expression of a machine compiles, and reads only names that exist where it stands."""

from __future__ import annotations

from typing import Any

from hfsm.checks.context import CheckContext, call_states, choice_states
from hfsm.expr import ExprSyntaxError, Names, compile_expr
from hfsm.library import MachineFile
from hfsm.model import IfBranch
from hfsm.spec import type_ok
from hfsm.values import compile_value

Where = tuple[str | int, ...]


def _value(ctx: CheckContext, mf: MachineFile, where: Where, value: Any, names: Names) -> None:
    errors: list[str] = []
    compile_value(value, names, errors)
    for message in errors:
        ctx.error(mf, where, "E314", message)


def _timer(ctx: CheckContext, mf: MachineFile, where: Where, timer: float | str | None, names: Names) -> None:
    if isinstance(timer, str):
        _value(ctx, mf, where, timer, names)


def check_expressions(ctx: CheckContext, mf: MachineFile) -> None:
    m = mf.model
    with_vars = Names(m.params, m.vars)
    _timer(ctx, mf, ("timer",), m.timer, Names(m.params, None))
    for name, expr in m.outputs.items():
        _value(ctx, mf, ("outputs", name), expr, with_vars)
    for name, state in call_states(m):
        _timer(ctx, mf, ("states", name, "timer"), state.timer, with_vars)
        for key, value in state.with_.items():
            _value(ctx, mf, ("states", name, "with", key), value, with_vars)
    for name, choice in choice_states(m):
        for i, branch in enumerate(choice.choose):
            if isinstance(branch, IfBranch):
                try:
                    compile_expr(branch.condition, with_vars)
                except ExprSyntaxError as exc:
                    ctx.error(mf, ("states", name, "choose", i, "if"), "E314", str(exc))


def check_param_defaults(ctx: CheckContext, mf: MachineFile) -> None:
    for name, param in mf.model.params.items():
        if not param.required and not type_ok(param.default, param.type):
            message = f"default {param.default!r} of param '{name}' is not a {param.type}"
            ctx.error(mf, ("params", name, "default"), "E306", message)
