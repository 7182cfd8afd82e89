"""Short texts for labels: call lines with abbreviated arguments, timers, parameter lists, wrapping."""

from __future__ import annotations

import json
import math
import re
import textwrap
from collections.abc import Mapping
from typing import Any

from hfsm.expr import ExprSyntaxError, ExprValueError, Names, Scope, compile_expr
from hfsm.model import Param, Retry

ELLIPSIS = "\u2026"
TIMES = "\u00d7"  # before a count: visits, arcs taken
VALUE_WIDTH = 18  # characters of one argument's value
LINE_WIDTH = 34  # characters of one line of a call
CONDITION_WIDTH = 30  # characters of one line of an arc's condition; longer ones wrap, never cut
LABEL_WIDTH = 40  # an arc's merged labels stay on one line up to this width
_WHOLE_EXPR = re.compile(r"^\$\{(.*)\}$", re.DOTALL)
_SENTENCE_END = re.compile(r"(?<=[.!?])\s+(?=\S)")


def shorten(text: str, width: int) -> str:
    """One line of at most `width` characters, cut with an ellipsis."""
    flat = " ".join(text.split())
    return flat if len(flat) <= width else flat[: max(width - 1, 1)].rstrip() + ELLIPSIS


def number(value: float) -> str:
    """The fewest digits that read back the same; a whole float without `.0`
    (docs/REFERENCE.md#expressions)."""
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


_LEADING_TEXT = re.compile(r"""^\s*(['"])([a-z0-9_]*)\1\s*\+""")


def scope(name: str) -> str:
    """A state's `scope:` as its label line (REFERENCE.md#scopes): `scope: pair` for a literal name; for an
    expression that starts with a literal, that literal and an ellipsis (`scope: pair_…`)."""
    found = _WHOLE_EXPR.match(name.strip())
    if found is None:
        return f"scope: {name}"
    leading = _LEADING_TEXT.match(found.group(1))
    if leading is not None:
        return f"scope: {leading.group(2)}{ELLIPSIS}"
    return f"scope: {shorten(found.group(1).strip(), VALUE_WIDTH)}"


def timer(t: float | str, params: Mapping[str, Param] | None = None) -> str:
    """A timer's duration: `30 s`, or its expression with its value from the params' defaults."""
    return duration(t, params, " s")


def duration(t: float | str, params: Mapping[str, Param] | None = None, unit: str = "") -> str:
    """A number, or an expression shown with its value from the params' defaults: `params.limit (30 s)`."""
    if not isinstance(t, str):
        return f"{number(t)}{unit}"
    match = _WHOLE_EXPR.match(t)
    source = match.group(1).strip() if match else t
    default = _by_default(source, params or {})
    shown = shorten(source, VALUE_WIDTH)
    return f"{shown} ({number(default)}{unit})" if default is not None else f"{shown}{unit}"


def _by_default(source: str, params: Mapping[str, Param]) -> float | None:
    """The expression's value when every param has its default; None when it has none or no number."""
    defaults = {name: p.default for name, p in params.items() if not p.required}
    try:
        got = compile_expr(source, Names(params=defaults, vars=None))(Scope(defaults, {}, ""))
    except (ExprSyntaxError, ExprValueError, ArithmeticError, TypeError, ValueError):
        return None
    return got if isinstance(got, int | float) and not isinstance(got, bool) else None


def wrap(text: str, width: int = CONDITION_WIDTH) -> str:
    """Text broken over lines (joined by newlines) of about `width` characters; nothing is cut."""
    flat = " ".join(text.split())
    return "\n".join(textwrap.wrap(flat, width, break_long_words=False, break_on_hyphens=False)) or text


def condition(order: int, text: str) -> str:
    return wrap(f"{order}: {text}")


def labels(parts: tuple[str, ...]) -> str:
    """An arc's labels: on one line joined by ` | ` when short, else one label under the other."""
    one = " | ".join(parts)
    return one if "\n" not in one and len(one) <= LABEL_WIDTH else "\n".join(parts)


def retry(r: Retry, params: Mapping[str, Param]) -> str:
    """`retry ×3: a, error` (a times sign), with a delay `retry ×3, 1.5 s apart: …`."""  # noqa: RUF002
    delay = "" if r.delay == 0 else f", {duration(r.delay, params, ' s')} apart"
    return wrap(f"retry {TIMES}{duration(r.times, params)}{delay}: {', '.join(r.on)}")


def params(items: Mapping[str, Param]) -> str:
    """`(steps: int = 3, role: str)`, or nothing when there are no parameters."""
    shown = []
    for name, p in items.items():
        default = "" if p.required else f" = {value(p.default)}"
        shown.append(f"{name}: {p.type}{default}")
    return f"({', '.join(shown)})" if shown else ""


def paragraph(text: str, width: int = 70, max_lines: int = 4) -> tuple[str, ...]:
    """A doc wrapped into lines: its first sentences that fit in `max_lines`, never cut mid-sentence.

    The first sentence is always shown whole, however long; a doc cut short ends with an ellipsis.
    """
    sentences = _SENTENCE_END.split(" ".join(text.split()))
    kept = sentences[:1]
    for sentence in sentences[1:]:
        if len(textwrap.wrap(" ".join([*kept, sentence]), width)) > max_lines:
            break
        kept.append(sentence)
    shown = " ".join(kept) + (f" {ELLIPSIS}" if len(kept) < len(sentences) else "")
    return tuple(textwrap.wrap(shown, width))
