"""What a caller needs to know of any behaviour: params, outcomes, failures, outputs."""

from __future__ import annotations

import math
import sys
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
    """Whether a value fits a declared param type; an int is accepted for a float."""
    if type_name == "any":
        return True
    if isinstance(value, bool):
        return type_name == "bool"
    if type_name == "float":  # an int too large for a float is not one
        return isinstance(value, float) or (isinstance(value, int) and abs(value) <= sys.float_info.max)
    expected = {"int": int, "bool": bool, "str": str, "list": list, "dict": dict}[type_name]
    return isinstance(value, expected)


def coerce(value: Any, type_name: str) -> Any:
    """A value that passed `type_ok`, as its declared type (ints become floats for float params)."""
    if type_name == "float" and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    return value


def is_finite_number(value: Any) -> bool:
    """A number that is finite as a float (an integer of 400 digits is not: it overflows one)."""
    if not isinstance(value, int | float) or isinstance(value, bool):
        return False
    return abs(value) <= sys.float_info.max if isinstance(value, int) else math.isfinite(value)
