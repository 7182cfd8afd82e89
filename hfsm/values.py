"""Values of `with` and `outputs`: literals in which `${…}` may stand at any depth, never in keys."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from hfsm import bounds
from hfsm.expr import ExprSyntaxError, ExprValueError, Fn, Names, Scope, bounded, compile_expr, short, to_text


@dataclass(frozen=True)
class Value:
    """A compiled value: `constant` when it holds no expression (then `fn` returns `literal`)."""

    fn: Fn
    constant: bool
    literal: Any = None
    is_expr: bool = False  # exactly "${…}": its type is known only when it runs


MAX_TEMPLATE = bounds.MAX_TEXT  # characters of a string holding `${…}`: its text could not be built
MAX_PARTS = 1_000  # `${…}` in one string


def split(text: str) -> list[str | tuple[str, int]]:
    """Split text into literal parts and (expression, its offset in text) parts; '${' without its
    '}' is an error, at the '${'; so is a string past MAX_TEMPLATE characters or MAX_PARTS `${…}`."""
    if len(text) > MAX_TEMPLATE:
        message = f"a string with '${{…}}' of {len(text):,} characters: the limit is {MAX_TEMPLATE:,}"
        raise ExprSyntaxError(message, 0, 0)
    parts: list[str | tuple[str, int]] = []
    i = count = 0
    while (start := text.find("${", i)) >= 0:
        count += 1
        if count > MAX_PARTS:
            message = f"more than {MAX_PARTS:,} '${{…}}' in one string (the limit)"
            raise ExprSyntaxError(message, start, start + 2)
        end = _closing(text, start + 2)
        if end < 0:
            raise ExprSyntaxError(f"'${{' without its closing '}}' in '{short(text)}'", start, start + 2)
        if start > i:
            parts.append(text[i:start])
        parts.append((text[start + 2 : end], start + 2))
        i = end + 1
    if i < len(text):
        parts.append(text[i:])
    return parts


_SPECIAL = re.compile(r"""['"{}]""")


def _closing(text: str, i: int) -> int:
    """The index of the '}' that closes a `${` whose expression starts at text[i], or -1."""
    depth, quote = 0, ""
    for found in _SPECIAL.finditer(text, i):
        ch, at = found.group(), found.start()
        if quote:
            quote = "" if ch == quote and text[at - 1] != "\\" else quote
        elif ch in "'\"":
            quote = ch
        elif ch == "{":
            depth += 1
        elif depth == 0:
            return at
        else:
            depth -= 1
    return -1


def compile_text(text: str, names: Names) -> Value:
    parts = split(text)
    if not any(isinstance(p, tuple) for p in parts):
        return Value(lambda s: text, True, text)
    if len(parts) == 1 and isinstance(parts[0], tuple):
        return Value(compile_expr(parts[0][0], names), False, is_expr=True)
    pieces: list[Callable[[Scope], str]] = []
    exprs = 0
    for part in parts:
        if isinstance(part, tuple):
            pieces.append(_as_text(compile_expr(part[0], names), exprs))
            exprs += 1
        else:
            pieces.append(_literal(part))
    return Value(lambda s: bounded("".join(p(s) for p in pieces)), False)


def _as_text(fn: Fn, index: int) -> Callable[[Scope], str]:
    """The `index`-th `${…}` of a text, as text; its index given to an error, for its position."""

    def text(s: Scope) -> str:
        try:
            return to_text(fn(s))
        except ExprValueError as exc:
            exc.where = (index, *exc.where)
            raise

    return text


def _at(key: str | int, value: Value) -> Callable[[Scope], Any]:
    """A dict's or a list's item, evaluated; its key given to an error, for its position."""
    fn = value.fn

    def item(s: Scope) -> Any:
        try:
            return fn(s)
        except ExprValueError as exc:
            exc.where = (key, *exc.where)
            raise

    return item


def _literal(text: str) -> Callable[[Scope], str]:
    return lambda s: text


def compile_value(value: Any, names: Names, errors: list[str] | None = None) -> Value:
    """Compile a literal tree; expression errors are appended to `errors` (or raised)."""
    if isinstance(value, str):
        try:
            return compile_text(value, names)
        except ExprSyntaxError as exc:
            if errors is None:
                raise
            errors.append(str(exc))
            return Value(lambda s: value, True, value)
    if isinstance(value, dict):
        items = {k: compile_value(v, names, errors) for k, v in value.items()}
        if all(v.constant for v in items.values()):
            return Value(lambda s: value, True, value)
        fns = {k: _at(k, v) for k, v in items.items()}
        return Value(lambda s: bounded({k: fn(s) for k, fn in fns.items()}), False)
    if isinstance(value, list):
        elems = [compile_value(v, names, errors) for v in value]
        if all(v.constant for v in elems):
            return Value(lambda s: value, True, value)
        each = [_at(i, v) for i, v in enumerate(elems)]
        return Value(lambda s: bounded([fn(s) for fn in each]), False)
    return Value(lambda s: value, True, value)
