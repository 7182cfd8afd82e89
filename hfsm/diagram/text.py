"""Short texts for labels: call lines with abbreviated arguments, timers, parameter lists, wrapping."""

from __future__ import annotations

import json
import math
import re
import textwrap
from collections.abc import Mapping
from typing import Any

from hfsm.model import Param

ELLIPSIS = "\u2026"
TIMES = "\u00d7"  # before a count: visits, arcs taken
VALUE_WIDTH = 18  # characters of one argument's value
LINE_WIDTH = 34  # characters of one line of a call
CONDITION_WIDTH = 30
_WHOLE_EXPR = re.compile(r"^\$\{(.*)\}$", re.DOTALL)


def shorten(text: str, width: int) -> str:
    """One line of at most `width` characters, cut with an ellipsis."""
    flat = " ".join(text.split())
    return flat if len(flat) <= width else flat[: max(width - 1, 1)].rstrip() + ELLIPSIS


def number(value: float) -> str:
    """The fewest digits that read back the same; a whole float without `.0` (SPEC 7)."""
    if isinstance(value, int):
        return str(value)
    if not math.isfinite(value):
        return str(value)
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


def value(v: Any) -> str:
    """An argument as a reader of the machine file would write it: expressions bare, strings quoted."""
    return shorten(_plain(v), VALUE_WIDTH)


def _plain(v: Any) -> str:
    if isinstance(v, str):
        match = _WHOLE_EXPR.match(v)
        return match.group(1).strip() if match else json.dumps(v, ensure_ascii=False)
    if isinstance(v, bool) or v is None:
        return json.dumps(v)
    if isinstance(v, int | float):
        return number(v)
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {_plain(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(_plain(x) for x in v) + "]"
    return str(v)


def call(do: str, args: Mapping[str, Any]) -> tuple[str, ...]:
    """`do(k=v, …)` broken after commas into lines of about LINE_WIDTH characters."""
    parts = [f"{k}={value(v)}" for k, v in args.items()]
    lines: list[str] = []
    current = f"{do}("
    for i, part in enumerate(parts):
        piece = part + ("," if i < len(parts) - 1 else "")
        if current.endswith("(") or len(current) + 1 + len(piece) <= LINE_WIDTH:
            current += ("" if current.endswith("(") else " ") + piece
        else:
            lines.append(current)
            current = "  " + piece
    lines.append(current + ")")
    return tuple(lines)


def timer(t: float | str) -> str:
    """A timer's duration: `30 s`, or its expression."""
    if isinstance(t, str):
        match = _WHOLE_EXPR.match(t)
        return shorten(match.group(1).strip() if match else t, VALUE_WIDTH) + " s"
    return f"{number(t)} s"


def condition(order: int, text: str) -> str:
    return f"{order}: {shorten(text, CONDITION_WIDTH)}"


def params(items: Mapping[str, Param]) -> str:
    """`(steps: int = 3, role: str)`, or nothing when there are no parameters."""
    shown = []
    for name, p in items.items():
        default = "" if p.required else f" = {value(p.default)}"
        shown.append(f"{name}: {p.type}{default}")
    return f"({', '.join(shown)})" if shown else ""


def paragraph(text: str, width: int = 70, max_lines: int = 4) -> tuple[str, ...]:
    """A doc paragraph wrapped into a few lines."""
    lines = textwrap.wrap(" ".join(text.split()), width)
    if len(lines) > max_lines:
        lines = [*lines[: max_lines - 1], shorten(" ".join(lines[max_lines - 1 :]), width)]
    return tuple(lines)
