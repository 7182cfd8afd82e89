"""A finding as people read it: its one line, then the source line with a caret under the span.

    many.yaml:8:21: error[E300]: unknown behaviour 'exploraton'; did you mean 'exploration'?
       |
     8 |       explore: {do: exploraton, with: {speed: 2.0}}
       |                     ^^^^^^^^^^

The first line stays what tools parse (`FILE:LINE:COL: severity[CODE]: message`). Colour only on a
terminal, and never when NO_COLOR is set (https://no-color.org).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import TextIO

from wcwidth import wcswidth, wcwidth

from hfsm.errors import Finding, Severity, UserError
from hfsm.spans import finding_span
from hfsm.yamlio import decode, read_bytes

_RED, _YELLOW, _BLUE, _BOLD, _RESET = "\x1b[31m", "\x1b[33m", "\x1b[34m", "\x1b[1m", "\x1b[0m"
TAB = "    "

Source = Callable[[str], list[str] | None]


def use_colour(out: TextIO) -> bool:
    if os.environ.get("NO_COLOR"):
        return False
    isatty = getattr(out, "isatty", None)
    return bool(isatty and isatty())


def file_lines() -> Source:
    """Lines of the files findings name, each read once (None: not readable as text)."""
    cache: dict[str, list[str] | None] = {}

    def lines(file: str) -> list[str] | None:
        if file not in cache:
            cache[file] = _read(Path(file))
        return cache[file]

    return lines


def _read(path: Path) -> list[str] | None:
    """A file's lines as the reader takes them (a regular file, never a FIFO, not over MAX_BYTES)."""
    try:
        return decode(read_bytes(path, str(path)), str(path)).splitlines()
    except UserError:
        return None


def render(finding: Finding, source: list[str] | None, *, colour: bool = False) -> str:
    """The finding's line, and when its line exists in `source`, that line with carets under it."""
    head = finding.format()
    paint = _painter(colour)
    kind = _RED if finding.severity is Severity.ERROR else _YELLOW
    prefix = f"{finding.file}:{finding.line}:{finding.col}: "
    if colour and head.startswith(prefix):
        label, _, message = head[len(prefix) :].partition(": ")
        head = paint(_BOLD, prefix) + paint(_BOLD + kind, label) + paint(_BOLD, ": " + message)
    if source is None or not 0 < finding.line <= len(source):
        return head
    raw = source[finding.line - 1]
    start, end = finding_span(raw, finding)
    raw, start, end = _window(raw, start, end)
    text = raw.replace("\t", TAB)
    before, under = raw[: start - 1], raw[start - 1 : end - 1]
    number = str(finding.line)
    gutter = " " * len(number)
    bar = paint(_BLUE, "|")
    carets = " " * _width(before) + paint(_BOLD + kind, "^" * max(1, _width(under)))
    return "\n".join(
        [head, f"{gutter} {bar}", f"{paint(_BLUE, number)} {bar} {text}".rstrip(), f"{gutter} {bar} {carets}"]
    )


WIDE = 100  # characters of a source line shown around the span; a longer line is cut with '…'


def _window(raw: str, start: int, end: int) -> tuple[str, int, int]:
    """The part of a long line around the span (columns from 1, `end` just after it)."""
    if len(raw) <= WIDE:
        return raw, start, end
    first = max(0, start - 1 - WIDE // 3)
    last = min(len(raw), first + WIDE)
    head = "…" if first > 0 else ""
    tail = "…" if last < len(raw) else ""
    start = start - first + len(head)
    end = min(end, last + 1) - first + len(head)
    return head + raw[first:last] + tail, start, max(end, start + 1)


def _width(text: str) -> int:
    """Terminal columns of `text` as shown: wide characters (中, most emoji) take two, combining marks
    none, a tab four; a character the terminal cannot print counts one (it is shown as something)."""
    text = text.replace("\t", TAB)
    width = wcswidth(text)
    if width >= 0:
        return width
    return sum(1 if each < 0 else each for each in map(wcwidth, text))


def _painter(colour: bool) -> Callable[[str, str], str]:
    if not colour:
        return lambda code, text: text
    return lambda code, text: f"{code}{text}{_RESET}"
