"""A person's hint for libyaml's syntax errors: a tab, an indentation that does not line up,
an unquoted `: ` or `#`, a quote never closed."""

from __future__ import annotations

import re
from typing import Any

_KEY = re.compile(r"^(\s*)(?:-\s+)*[^\s#'\"][^:#]*:(\s|$)")


def hint(problem: str, lines: list[str], line: int, col: int) -> str:
    """The hint for the error at 1-based (line, col) of `lines`, or ''."""
    here = lines[line - 1] if 0 < line <= len(lines) else ""
    before = _previous(lines, line)
    if "tab" in problem or "\t" in here[: len(here) - len(here.lstrip())] or here[col - 1 : col] == "\t":
        return "a tab: YAML indents with spaces only"
    if "mapping values are not allowed" in problem:
        if before is not None and _indent(here) > _indent(before) and _has_value(before):
            return (
                f"this line is indented deeper than line {before[1]} above it, which already has a "
                "value: line its key up with the keys above, or quote a value that holds ': '"
            )
        return "a second ': ' on one line: quote a value that holds ': ' (text: \"a: b\")"
    if "expected key" in problem or "expected '-' indicator" in problem or "<block end>" in problem:
        return _indentation(lines, line)
    if "unexpected end of stream" in problem and "quoted" in problem:
        return "a quote is opened and never closed"
    if "cannot start any token" in problem:
        ch = here[col - 1 : col]
        return f"'{ch}' cannot start a plain value: quote the value" if ch.strip() else ""
    near = here + "\n" + (before[0] if before else "")
    if "flow" in problem and re.search(r"(^|[\s\[{,])#", near):
        return "'#' after a space or a bracket starts a comment: quote a value that holds '#'"
    if "flow" in problem and ": " in here:
        return "inside [ ] or { }, quote a value that holds ': ' or ','"
    return ""


def _indent(entry: tuple[str, int] | str) -> int:
    text = entry[0] if isinstance(entry, tuple) else entry
    return len(text) - len(text.lstrip(" "))


def _previous(lines: list[str], line: int) -> tuple[str, int] | None:
    for n in range(line - 1, 0, -1):
        text = lines[n - 1]
        if text.strip() and not text.lstrip().startswith("#"):
            return text, n
    return None


def _has_value(entry: tuple[str, int]) -> bool:
    text = entry[0].split(" #", 1)[0].rstrip()
    key = _KEY.match(text)
    return key is not None and bool(text[key.end() :].strip())


def _indentation(lines: list[str], line: int) -> str:
    here = lines[line - 1] if 0 < line <= len(lines) else ""
    if not here.strip():
        return ""
    columns = sorted(
        {_indent(t) + 1 for t in lines[max(0, line - 40) : line - 1] if t.strip() and _KEY.match(t)}
    )
    shown = ", ".join(str(c) for c in columns[-4:])
    where = f" (the keys above start at column {shown})" if columns else ""
    return f"the indentation does not line up: this line starts at column {_indent(here) + 1}{where}"


_CLOSE = {"{": "}", "[": "]"}


def unclosed(exc: Any, lines: list[str]) -> tuple[int, int, str, str] | None:
    """A `{`, a `[` or a quote never closed: (line, col, code, message) at it, or None.

    libyaml notices only where the flow collection should have ended (often the next line); its
    context mark is the bracket that was opened, and the bracket's line does not close it."""
    context = str(exc.context or "")
    start, end = exc.context_mark, exc.problem_mark
    if start is None or end is None:
        return None
    if "while scanning a quoted scalar" in context and "end of stream" in str(exc.problem):
        quote = (lines[start.line] if start.line < len(lines) else "")[start.column : start.column + 1] or "'"
        message = f"YAML syntax: this {quote!r} is never closed: add {quote!r} where the text ends"
        return start.line + 1, start.column + 1, "E100", message
    if "while parsing a flow" not in context:
        return None
    text = lines[start.line] if start.line < len(lines) else ""
    bracket = text[start.column : start.column + 1]
    if bracket not in _CLOSE or (end.line == start.line and _closes(text, start.column)):
        return None
    if end.line == start.line and ": " in text[start.column :]:
        return None  # a `: ` inside the brackets, not a missing bracket: the usual hint says so
    message = (
        f"YAML syntax: this '{bracket}' is never closed: add '{_CLOSE[bracket]}' where its "
        f"{'mapping' if bracket == '{' else 'list'} ends (at the end of line {start.line + 1}?)"
    )
    return start.line + 1, start.column + 1, "E100", message


def _closes(text: str, at: int) -> bool:
    depth, quote = 0, ""
    for char in text[at:]:
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char in "[{":
            depth += 1
        elif char in "]}":
            depth -= 1
            if depth == 0:
                return True
        elif char == "#":
            break
    return False
