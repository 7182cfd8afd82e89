"""What an expression does when it runs: operators, functions and built values, checked against
the limits of hfsm.bounds; a failure is ExprValueError (the event `error`)."""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable
from typing import Any

from hfsm import bounds
from hfsm.expr.funcs import is_number, kind
from hfsm.expr.scope import ExprValueError, Fn, Scope

BIN: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
}
CMP: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq,
    ast.NotEq: operator.ne,
    ast.Lt: operator.lt,
    ast.LtE: operator.le,
    ast.Gt: operator.gt,
    ast.GtE: operator.ge,
    ast.In: lambda a, b: operator.contains(b, a),
    ast.NotIn: lambda a, b: not operator.contains(b, a),
}
LITERAL_NAMES = {"true": True, "false": False, "null": None}


_SYMBOLS: dict[type, str] = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.FloorDiv: "//"}


def arith(op: type, fn: Callable[[Any, Any], Any]) -> Callable[[Any, Any], Any]:
    def apply(a: Any, b: Any) -> Any:
        both_numbers = is_number(a) and is_number(b)
        joinable = op is ast.Add and type(a) is type(b) and isinstance(a, str | list)
        if not (both_numbers or joinable):
            raise ExprValueError(f"cannot apply '{_SYMBOLS.get(op, '%')}' to {kind(a)} and {kind(b)}")
        return _bounded(op, fn, a, b)

    return apply


def _bounded(op: type, fn: Callable[[Any, Any], Any], a: Any, b: Any) -> Any:
    """Apply `fn`; refuse a result past the limits of hfsm.bounds, a big product before it is made."""
    try:
        if op is ast.Mult and a.__class__ is int and b.__class__ is int:
            bounds.product_fits(a, b)
        elif op is ast.Add and not is_number(a):
            bounds.joined_fits(a, b)
            return bounds.check_value(fn(a, b))
        result = fn(a, b)
        if result.__class__ is float:
            return bounds.check_float(result)
        return bounds.check_int(result)
    except bounds.LimitError as exc:
        raise ExprValueError(str(exc)) from None
    except OverflowError:
        raise ExprValueError("the result is too large for a number") from None


def bounded(value: Any) -> Any:
    """A built list, dict or string, checked against the limits of hfsm.bounds."""
    try:
        return bounds.check_value(value)
    except bounds.LimitError as exc:
        raise ExprValueError(str(exc)) from None


def all_of(parts: list[Fn], s: Scope) -> Any:
    value: Any = True
    for part in parts:
        value = part(s)
        if not value:
            return value
    return value


def any_of(parts: list[Fn], s: Scope) -> Any:
    value: Any = False
    for part in parts:
        value = part(s)
        if value:
            return value
    return value
