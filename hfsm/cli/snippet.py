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

from hfsm.errors import Finding, Severity
from hfsm.spans import finding_span

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
            try:
                cache[file] = Path(file).read_text(encoding="utf-8").splitlines()
            except (OSError, UnicodeDecodeError):
                cache[file] = None
        return cache[file]

    return lines


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


SHOWN = 160  # characters of a long source line shown around the caret


def _window(raw: str, start: int, end: int) -> tuple[str, int, int]:
    """A line longer than SHOWN cut around the span, `…` where it is cut; the span's 1-based
    [start, end) columns in what is shown."""
    if len(raw) <= SHOWN:
        return raw, start, end
    first = max(0, min(start - 1 - SHOWN // 4, len(raw) - SHOWN))
    lead = "…" if first else ""
    tail = "…" if first + SHOWN < len(raw) else ""
    shown = lead + raw[first : first + SHOWN] + tail
    return shown, start - first + len(lead), min(end - first, SHOWN + 1) + len(lead)


def _width(text: str) -> int:
    return len(text.replace("\t", TAB))


def _painter(colour: bool) -> Callable[[str, str], str]:
    if not colour:
        return lambda code, text: text
    return lambda code, text: f"{code}{text}{_RESET}"
