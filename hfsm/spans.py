"""What a finding's position points at in its source line: the key, the value, the bracket, the name.

A finding carries where something starts (line and column); the caret under a message and the
range an editor underlines both need where it ends. Both read it here, from the line's text, so the
terminal and the language server underline the same characters.
"""

from __future__ import annotations

import re

_NAME = re.compile(r"[A-Za-z0-9_.]+")
_FLOW_END = ",]}"
_PAIRS = {"[": "]", "{": "}"}


def span(line: str, col: int, *, width: int = 0) -> tuple[int, int]:
    """1-based [start, end) columns of what starts at `col` of `line`; `width`: a known length."""
    start = max(1, min(col, len(line) + 1))
    if width > 0:
        return start, min(len(line) + 1, start + width) if start <= len(line) else start + 1
    i = start - 1
    if i >= len(line):
        return start, start + 1
    char = line[i]
    if char in "'\"":
        return start, _quoted(line, i) + 1
    if char in _PAIRS:
        return start, _bracketed(line, i) + 1
    if _inside_expression(line, i) and _NAME.match(line, i):
        match = _NAME.match(line, i)
        assert match is not None
        return start, match.end() + 1
    return start, _plain(line, i) + 1


def _quoted(line: str, i: int) -> int:
    """The index after the closing quote (or the line's end when it is not closed here)."""
    quote, j = line[i], i + 1
    while j < len(line):
        if quote == '"' and line[j] == "\\":
            j += 2
            continue
        if line[j] == quote:
            if quote == "'" and line[j + 1 : j + 2] == "'":
                j += 2
                continue
            return j + 1
        j += 1
    return len(line.rstrip())


def _bracketed(line: str, i: int) -> int:
    """The index after the bracket that closes the one at `i`; one character if it is not closed on
    this line (the caret then marks the opening bracket alone)."""
    depth, j, quote = 0, i, ""
    while j < len(line):
        char = line[j]
        if quote:
            if char == quote:
                quote = ""
        elif char in "'\"":
            quote = char
        elif char in _PAIRS:
            depth += 1
        elif char in "]}":
            depth -= 1
            if depth == 0:
                return j + 1
        elif char == "#" and line[j - 1 : j] in (" ", "\t"):
            break
        j += 1
    return i + 1


def _plain(line: str, i: int) -> int:
    """The index after a plain key or value: up to `: `, a comment, a flow separator or the end."""
    in_flow = _open_brackets(line, i) > 0
    j = i
    while j < len(line):
        char = line[j]
        if char == ":" and (j + 1 == len(line) or line[j + 1] in " \t" or (in_flow and line[j + 1] in ",]}")):
            break
        if char == "#" and j > i and line[j - 1] in " \t":
            break
        if in_flow and char in _FLOW_END:
            break
        j += 1
    while j > i + 1 and line[j - 1] in " \t":
        j -= 1
    return max(j, i + 1)


def _open_brackets(line: str, i: int) -> int:
    depth, quote = 0, ""
    for char in line[:i]:
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char in _PAIRS:
            depth += 1
        elif char in "]}":
            depth = max(0, depth - 1)
    return depth


def _inside_expression(line: str, i: int) -> bool:
    """Whether `i` is inside a `${…}` (or a quoted condition) and not at its start."""
    opened = line.rfind("${", 0, i)
    if opened >= 0 and line.find("}", opened, i) < 0:
        return i > opened + 1
    before = line[:i].rstrip()
    return bool(before) and before[-1] not in ":-[{,'\"" and not before.endswith("- ")
