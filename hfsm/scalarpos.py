"""Where a character of a YAML string's value stands in the file, for an error inside the string.

The value differs from what the file shows: quotes, escapes (`\\n`, `''`), folded line breaks and
the indentation of block scalars. The scalar is decoded again from the file's text, character by
character, each checked against the value; when one differs (a form this does not follow, an
anchor, a tag), the answer is None and the finding stays at the start of the string.
"""

from __future__ import annotations

from collections.abc import Generator, Iterator
from dataclasses import replace
from functools import lru_cache
from typing import Any

from hfsm.errors import Finding
from hfsm.yamlio import Document, Path_

Pos = tuple[int, int]
_ESCAPES = {
    "0": "\0", "a": "\a", "b": "\b", "t": "\t", "\t": "\t", "n": "\n", "v": "\v", "f": "\f", "r": "\r",
    "e": "\x1b", " ": " ", '"': '"', "/": "/", "\\": "\\", "N": "\x85", "_": "\xa0", "L": "\u2028",
    "P": "\u2029",
}  # fmt: skip
_HEX = {"x": 2, "u": 4, "U": 8}
MAX_WALK = 200_000  # characters of a value followed; past it, the start of the string


@lru_cache(maxsize=4)
def _line_starts(text: str) -> tuple[int, ...]:
    starts = [0]
    at = text.find("\n")
    while at >= 0:
        starts.append(at + 1)
        at = text.find("\n", at + 1)
    return tuple(starts)


def inside_string(doc: Document, path: Path_, found: Finding, span: tuple[int, int]) -> Finding:
    """`found` moved to the characters `span` of the string at `path`, when they can be placed."""
    start = doc.values.get(path)
    value: Any = doc.data
    for part in path:
        try:
            value = value[part]
        except (KeyError, IndexError, TypeError):
            return found
    if start is None or not isinstance(value, str) or not doc.text:
        return found
    placed = locate(doc.text, start, value, span)
    if placed is None:
        return found
    (line, col), end = placed
    return replace(found, line=line, col=col, end=end)


def locate(text: str, start: Pos, value: str, offsets: tuple[int, int]) -> tuple[Pos, Pos] | None:
    """The file positions (1-based line and column) of two offsets of `value`, the string whose
    scalar starts at `start` in `text`; the second is exclusive (just after the span)."""
    first, last = offsets
    if not 0 <= first <= last <= len(value) or first > MAX_WALK:
        return None
    last = min(last, max(first + 1, MAX_WALK))  # past MAX_WALK, the span ends early
    starts = _line_starts(text)
    if not 1 <= start[0] <= len(starts):
        return None
    need = min(len(value), max(first + 1, last))
    raw: list[int] = []  # where each character of the value stands in the text
    if need:
        for char, at in _decoded(text, starts[start[0] - 1] + start[1] - 1):
            if char != value[len(raw)]:
                return None
            raw.append(at)
            if len(raw) == need:
                break
    if len(raw) < need:
        return None
    return _pos(starts, _raw(raw, first)), _pos(starts, _raw(raw, last))


def _raw(raw: list[int], offset: int) -> int:
    if offset < len(raw):
        return raw[offset]
    return raw[-1] + 1 if raw else 0


def _pos(starts: tuple[int, ...], index: int) -> Pos:
    line = max(0, _bisect(starts, index))
    return line + 1, index - starts[line] + 1


def _bisect(starts: tuple[int, ...], index: int) -> int:
    low, high = 0, len(starts)
    while low < high:
        mid = (low + high) // 2
        if starts[mid] <= index:
            low = mid + 1
        else:
            high = mid
    return low - 1


def _decoded(text: str, i: int) -> Iterator[tuple[str, int]]:
    """The characters of the scalar starting at text[i], each with its index in text."""
    if i >= len(text):
        return
    style = text[i]
    if style in "|>":
        yield from _block(text, i)
    elif style in "'\"":
        yield from _flow(text, i + 1, style)
    elif style not in "&!*":
        yield from _flow(text, i, "")


def _flow(text: str, i: int, quote: str) -> Iterator[tuple[str, int]]:
    """A plain or quoted scalar: escapes, doubled single quotes and folded line breaks."""
    n = len(text)
    while i < n:
        char = text[i]
        if quote and char == quote:
            if quote == "'" and text[i + 1 : i + 2] == "'":
                yield "'", i
                i += 2
                continue
            return
        if char == "\\" and quote == '"':
            i = yield from _escape(text, i)
            continue
        if char in " \t\r\n":
            j = i
            while j < n and text[j] in " \t":
                j += 1
            if j < n and text[j] in "\r\n":
                i = yield from _fold(text, j)
                continue
        yield char, i
        i += 1


def _escape(text: str, i: int) -> Generator[tuple[str, int], None, int]:
    code = text[i + 1 : i + 2]
    if code in ("\n", "\r"):  # an escaped line break: nothing, nor the next line's indentation
        j = i + 1
        while j < len(text) and text[j] in " \t\r\n":
            j += 1
        return j
    if code in _HEX:
        digits = text[i + 2 : i + 2 + _HEX[code]]
        try:
            yield chr(int(digits, 16)), i
        except ValueError:
            return len(text)
        return i + 2 + _HEX[code]
    if code in _ESCAPES:
        yield _ESCAPES[code], i
        return i + 2
    return len(text)


def _fold(text: str, j: int) -> Generator[tuple[str, int], None, int]:
    """Line breaks at text[j] inside a flow scalar: one is a space, each blank line after is `\\n`."""
    breaks, k = 0, j
    while k < len(text) and text[k] in " \t\r\n":
        if text[k] == "\n":
            breaks += 1
        k += 1
    if breaks == 1:
        yield " ", j
    for _ in range(breaks - 1):
        yield "\n", j
    return k


def _block(text: str, i: int) -> Iterator[tuple[str, int]]:
    """A literal (`|`) or folded (`>`) block scalar with no indentation indicator."""
    folded = text[i] == ">"
    header_end = text.find("\n", i)
    if header_end < 0 or any(c.isdigit() for c in text[i:header_end].split("#")[0]):
        return
    lines = _block_lines(text, header_end + 1)
    if not lines:
        return
    indents = [len(line) - len(line.lstrip(" ")) for line, _ in lines if line.strip()]
    indent = min(indents, default=0)
    for number, (line, at) in enumerate(lines):
        body = line[indent:]
        if folded and body[:1] in (" ", "\t"):
            return  # a more-indented line of a folded scalar: not followed here
        for k, char in enumerate(body):
            yield char, at + indent + k
        if number + 1 < len(lines):
            blank_next = not lines[number + 1][0].strip()
            joined = folded and body and not blank_next
            yield (" " if joined else "\n"), at + len(line)


def _block_lines(text: str, i: int) -> list[tuple[str, int]]:
    """The lines of a block scalar's body from text[i]: until a line indented less than its first."""
    lines: list[tuple[str, int]] = []
    indent = None
    while i < len(text):
        end = text.find("\n", i)
        end = len(text) if end < 0 else end
        line = text[i:end].rstrip("\r")
        if line.strip():
            here = len(line) - len(line.lstrip(" "))
            if indent is None:
                indent = here
            elif here < indent:
                break
        lines.append((line, i))
        i = end + 1
    return lines
