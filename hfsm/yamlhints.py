"""A person's hint for libyaml's syntax errors: a tab, an indentation that does not line up,
an unquoted `: ` or `#`, a quote never closed."""

from __future__ import annotations

import re

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
