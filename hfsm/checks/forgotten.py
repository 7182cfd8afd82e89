"""The forgotten `${…}` (issue 13): a string that reads like an expression but is not wrapped is
taken as text, and fails far away and much later. Warned here, at the string (W405)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from hfsm.checks.context import CheckContext, call_states, parallel_states
from hfsm.checks.expressions import strings_in
from hfsm.expr import ExprSyntaxError, Names, compile_expr, reads
from hfsm.library import MachineFile
from hfsm.model import CallState, Region

Where = tuple[str | int, ...]
_ROOTS = ("vars.", "params.", "agent.", "state.", "machine.", "in.")


class _Every:
    """Every name: whether a var or param exists is the business of other checks."""

    def __contains__(self, name: object) -> bool:
        return True

    def __iter__(self) -> Iterator[str]:
        return iter(())

    def __len__(self) -> int:
        return 0


_ANY_NAMES = Names(_Every(), _Every())


def reads_like_expression(text: str) -> bool:
    """`vars.lap + 1`, `params.target`: parses as an expression and reads a name of
    docs/REFERENCE.md#expressions."""
    if "${" in text or "." not in text or not any(root in text for root in _ROOTS):
        return False  # most strings: no need to parse them
    try:
        compile_expr(text, _ANY_NAMES)  # only what the language allows: `vars.n is big` is prose
    except ExprSyntaxError:
        return False
    return any(name.startswith(_ROOTS) for name in reads(text))


def wrapped(text: str) -> str:
    return "${" + text.strip() + "}"


def check_forgotten_wraps(ctx: CheckContext, mf: MachineFile) -> None:
    for name, value in mf.model.outputs.items():
        _strings(ctx, mf, ("outputs", name), value)
    for name, state in call_states(mf.model):
        _call(ctx, mf, ("states", name), state)
    for name, parallel in parallel_states(mf.model):
        for region_name, region in parallel.parallel.items():
            _call(ctx, mf, ("states", name, "parallel", region_name), region)


def _call(ctx: CheckContext, mf: MachineFile, where: Where, call: CallState | Region) -> None:
    spec = ctx.specs.get(call.do)
    for key, value in call.with_.items():
        at = (*where, "with", key)
        if spec is not None and spec.open_params and key in mf.model.vars:
            if _sets_number_to_text(ctx, mf, at, key, value):
                continue
        elif spec is not None and key in spec.params and spec.params[key].type in ("int", "float", "bool"):
            continue  # a string there is an error (E306), which says how to wrap it
        _strings(ctx, mf, at, value)


def _sets_number_to_text(ctx: CheckContext, mf: MachineFile, at: Where, var: str, value: Any) -> bool:
    initial = mf.model.vars[var]
    typed = isinstance(initial, bool | int | float)
    if not (typed and isinstance(value, str) and "${" not in value):
        return False
    kind = type(initial).__name__
    fix = f"; write '{wrapped(value)}'" if reads_like_expression(value) else ""
    message = f"var '{var}' starts as {kind}, but this sets it to the text '{value}'{fix}"
    ctx.warn(mf, at, "W405", message)
    return True


def _strings(ctx: CheckContext, mf: MachineFile, where: Where, value: Any) -> None:
    for path, text in strings_in(where, value):
        if reads_like_expression(text):
            message = f"'{text}' reads like an expression but is taken as text; write '{wrapped(text)}'"
            ctx.warn(mf, path, "W405", message)
