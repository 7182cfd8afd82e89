"""The functions an expression may call: their arity, checked when the file is loaded, and what they
accept, checked when they run. A value outside a function's domain is ExprValueError (the event
`error`), and so is a float result that is not finite."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from hfsm import bounds
from hfsm.expr.scope import ExprValueError


@dataclass(frozen=True)
class Func:
    fn: Callable[..., Any]
    least: int  # arguments
    most: int | None  # None: any number
    doc: str

    def arity(self) -> str:
        if self.most == self.least:
            return f"{self.least} argument{'s' if self.least != 1 else ''}"
        if self.most is None:
            return f"at least {self.least} arguments"
        return f"{self.least} to {self.most} arguments"


def kind(value: Any) -> str:
    return {bool: "bool", int: "int", float: "float", str: "str", list: "list", dict: "dict"}.get(
        type(value), "null" if value is None else type(value).__name__
    )


def is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _number(name: str, value: Any) -> float | int:
    if not is_number(value):
        raise ExprValueError(f"{name}() takes numbers, not {kind(value)}")
    number: float | int = value
    return number


def _list(name: str, value: Any) -> list[Any]:
    if not isinstance(value, list):
        raise ExprValueError(f"{name}() takes a list, not {kind(value)}")
    return value


def _finite(name: str, compute: Callable[[], Any]) -> Any:
    """The result of a math function, refused when it is outside the domain, too large or not finite."""
    try:
        result = compute()
    except ValueError:
        raise ExprValueError(f"{name}(): an argument outside the function's domain") from None
    except OverflowError:
        raise ExprValueError(f"{name}(): a number too large for a float") from None
    try:
        return bounds.check_float(result) if isinstance(result, float) else bounds.check_int(result)
    except bounds.LimitError as exc:
        raise ExprValueError(f"{name}(): {exc}") from None


def _math(name: str, fn: Callable[..., Any]) -> Callable[..., Any]:
    def call(*args: Any) -> Any:
        numbers = [_number(name, a) for a in args]
        return _finite(name, lambda: fn(*numbers))

    return call


def _len(value: Any) -> int:
    if not isinstance(value, str | list | dict):
        raise ExprValueError(f"len() of {kind(value)}")
    return len(value)


def _round(value: Any, digits: Any = None) -> Any:
    whole = digits is None or (isinstance(digits, int) and not isinstance(digits, bool))
    if not is_number(value) or not whole:
        raise ExprValueError("round() takes a number and an optional whole number of digits")
    if digits is None:
        return _finite("round", lambda: round(value))
    return _finite("round", lambda: round(value, max(-10_000, min(10_000, digits))))


def _abs(value: Any) -> Any:
    return abs(_number("abs", value))


def _extreme(name: str, pick: Callable[..., Any]) -> Callable[..., Any]:
    def call(*args: Any) -> Any:
        items = _list(name, args[0]) if len(args) == 1 else list(args)
        if not items:
            raise ExprValueError(f"{name}() of an empty list")
        return pick(_sortable(name, items))

    return call


def _sortable(name: str, items: Sequence[Any]) -> Sequence[Any]:
    """Items that compare with each other: all numbers or all strings."""
    if all(is_number(i) for i in items) or all(isinstance(i, str) for i in items):
        return items
    kinds = sorted({kind(i) for i in items})
    raise ExprValueError(f"{name}() of a mix of {', '.join(kinds)}: only numbers or only strings compare")


def _sum(values: Any) -> Any:
    numbers = [_number("sum", v) for v in _list("sum", values)]
    return _finite("sum", lambda: sum(numbers))


def _sorted(values: Any) -> list[Any]:
    return sorted(_sortable("sorted", _list("sorted", values)))


def _any(values: Any) -> bool:
    return any(_list("any", values))


def _all(values: Any) -> bool:
    return all(_list("all", values))


def _rounding(name: str, fn: Callable[[float], int]) -> Callable[[Any], int]:
    def call(value: Any) -> int:
        number = _number(name, value)
        result: int = number if isinstance(number, int) else _finite(name, lambda: fn(number))
        return result

    return call


FUNCS: dict[str, Func] = {
    "abs": Func(_abs, 1, 1, "the absolute value of a number"),
    "min": Func(_extreme("min", min), 1, None, "the least of a list, or of the arguments"),
    "max": Func(_extreme("max", max), 1, None, "the greatest of a list, or of the arguments"),
    "round": Func(_round, 1, 2, "a number rounded to a whole number, or to a number of digits"),
    "len": Func(_len, 1, 1, "the length of a string, a list or a dict"),
    "sum": Func(_sum, 1, 1, "the sum of a list of numbers"),
    "sorted": Func(_sorted, 1, 1, "a list of numbers, or of strings, in increasing order"),
    "any": Func(_any, 1, 1, "whether any element of a list is true"),
    "all": Func(_all, 1, 1, "whether every element of a list is true"),
    "sqrt": Func(_math("sqrt", math.sqrt), 1, 1, "the square root of a number >= 0"),
    "hypot": Func(_math("hypot", math.hypot), 2, None, "the length of a vector: sqrt(x*x + y*y ...)"),
    "sin": Func(_math("sin", math.sin), 1, 1, "the sine of an angle in radians"),
    "cos": Func(_math("cos", math.cos), 1, 1, "the cosine of an angle in radians"),
    "tan": Func(_math("tan", math.tan), 1, 1, "the tangent of an angle in radians"),
    "asin": Func(_math("asin", math.asin), 1, 1, "the angle in radians of a sine in [-1, 1]"),
    "acos": Func(_math("acos", math.acos), 1, 1, "the angle in radians of a cosine in [-1, 1]"),
    "atan": Func(_math("atan", math.atan), 1, 1, "the angle in radians of a tangent"),
    "atan2": Func(_math("atan2", math.atan2), 2, 2, "atan2(y, x): the angle in radians of the point (x, y)"),
    "degrees": Func(_math("degrees", math.degrees), 1, 1, "an angle in radians, in degrees"),
    "radians": Func(_math("radians", math.radians), 1, 1, "an angle in degrees, in radians"),
    "floor": Func(_rounding("floor", math.floor), 1, 1, "the greatest whole number <= a number"),
    "ceil": Func(_rounding("ceil", math.ceil), 1, 1, "the least whole number >= a number"),
}
