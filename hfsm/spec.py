"""What a caller needs to know of any behaviour: params, outcomes, failures, outputs."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

Kind = Literal["builtin", "primitive", "machine"]
TYPE_NAMES = ("int", "float", "bool", "str", "list", "dict", "any")


@dataclass(frozen=True)
class ParamSpec:
    name: str
    type: str  # one of TYPE_NAMES
    required: bool = True
    default: Any = None
    doc: str = ""
    choices: tuple[str, ...] = ()  # the values a literal may take (empty: any of its type)


@dataclass(frozen=True)
class BehaviourSpec:
    name: str
    kind: Kind
    params: dict[str, ParamSpec]
    outcomes: tuple[str, ...]
    failures: frozenset[str] = frozenset()
    outputs: frozenset[str] | None = frozenset()  # None: open (any name may be saved)
    doc: str = ""
    world: str | None = None  # the world a primitive needs, e.g. "sim"
    open_params: bool = False  # `set` takes the caller's vars as params


def type_ok(value: Any, type_name: str) -> bool:
    """Whether a value fits a declared param type; an int is accepted for a float when one can hold it."""
    if type_name == "any":
        return True
    if isinstance(value, bool):
        return type_name == "bool"
    if type_name == "float":
        return isinstance(value, float) or (isinstance(value, int) and fits_float(value))
    expected = {"int": int, "bool": bool, "str": str, "list": list, "dict": dict}[type_name]
    return isinstance(value, expected)


def coerce(value: Any, type_name: str) -> Any:
    """A value that passed `type_ok`, as its declared type (ints become floats for float params)."""
    if type_name == "float" and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    return value


def fits_float(value: int) -> bool:
    """Whether an integer converts to a float (a 400-digit one does not)."""
    return abs(value).bit_length() <= FLOAT_BITS and math.isfinite(float(value))


FLOAT_BITS = 1024  # a float's largest finite value is below 2**1024


def is_finite_number(value: Any) -> bool:
    if isinstance(value, bool) or not isinstance(value, int | float):
        return False
    return fits_float(value) if isinstance(value, int) else math.isfinite(value)


def shown(value: Any) -> str:
    """A value as messages quote it: an integer of many digits by its first digits and length."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value).bit_length() > 128:
        digits = len(str(abs(value)))
        kind = "too large for a float" if abs(value).bit_length() > FLOAT_BITS else "an integer"
        return f"{str(value)[:8]}... ({digits} digits, {kind})"
    return repr(value)
