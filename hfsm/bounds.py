"""Limits on the values that expressions build (docs/LANGUAGE.md, Limits), checked as they are built.

A machine that doubles a list or a string each tick, or squares an integer, would otherwise fill
memory or hang inside one multiplication; past a limit, the expression fails (the event `error`,
naming the limit) before the value is made.
"""

from __future__ import annotations

import math
from typing import Any


class LimitError(Exception):
    """A value past a limit; expressions turn it into ExprValueError (the event `error`)."""


MAX_TEXT = 100_000  # characters of a string
MAX_ITEMS = 100_000  # elements of a list or dict, counted through nesting (a shared one each time)
MAX_DEPTH = 100  # lists and dicts nested
MAX_DIGITS = 1_000  # decimal digits of an integer
_MAX_BITS = math.ceil(MAX_DIGITS * math.log2(10))


def check_int(value: int) -> int:
    if value.bit_length() > _MAX_BITS:
        raise LimitError(f"an integer of more than {MAX_DIGITS:,} digits (the limit)")
    return value


def check_float(value: float) -> float:
    if not math.isfinite(value):
        raise LimitError(f"the result is {value}, not a finite number")
    return value


def check_text(value: str) -> str:
    if len(value) > MAX_TEXT:
        raise LimitError(f"a string of more than {MAX_TEXT:,} characters (the limit)")
    return value


def check_scalar(value: Any) -> Any:
    cls = value.__class__
    if cls is int:
        return check_int(value)
    if cls is float:
        return check_float(value)
    if cls is str:
        return check_text(value)
    return value


def product_fits(a: int, b: int) -> None:
    """Refuse a product of integers too large before computing it (its bits: the sum, or one less)."""
    if abs(a).bit_length() + abs(b).bit_length() > _MAX_BITS + 1:
        raise LimitError(f"an integer of more than {MAX_DIGITS:,} digits (the limit)")


def joined_fits(a: str | list[Any], b: str | list[Any]) -> None:
    """Refuse a concatenation too long before making it."""
    if isinstance(a, str):
        if len(a) + len(b) > MAX_TEXT:
            raise LimitError(f"a string of more than {MAX_TEXT:,} characters (the limit)")
    elif len(a) + len(b) > MAX_ITEMS:
        raise LimitError(f"a list of more than {MAX_ITEMS:,} elements (the limit)")


def check_value(value: Any) -> Any:
    """Walk a built list or dict, stopping at the first limit passed: O(min(size, limits))."""
    if value.__class__ is str:
        return check_text(value)
    if value.__class__ is not list and value.__class__ is not dict:
        return value
    count = 0
    pending: list[tuple[Any, int]] = [(value, 1)]
    while pending:
        item, depth = pending.pop()
        if depth > MAX_DEPTH:
            raise LimitError(f"lists and dicts nested more than {MAX_DEPTH} deep (the limit)")
        children = item.values() if item.__class__ is dict else item
        count += len(children)
        if count > MAX_ITEMS:
            raise LimitError(f"a value of more than {MAX_ITEMS:,} elements (the limit)")
        for child in children:
            cls = child.__class__
            if cls is list or cls is dict:
                pending.append((child, depth + 1))
            elif cls is str and len(child) > MAX_TEXT:
                check_text(child)
    return value
