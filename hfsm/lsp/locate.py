"""What the cursor is on: a key or a value of the document (its path), or a name in an expression."""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from lsprotocol import types as lsp

from hfsm.spans import span
from hfsm.yamlio import Document, Path_

_DOTTED = re.compile(r"[A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*")


@dataclass(frozen=True)
class Node:
    path: Path_
    is_key: bool
    text: str  # the key, or the value as written, without its quotes
    range: lsp.Range  # of that text


def name_range(lines: Sequence[str], line: int, col: int) -> tuple[lsp.Range, str]:
    """The range and text of the key or scalar written at 1-based (line, col), quotes left out."""
    text = lines[line - 1] if 0 < line <= len(lines) else ""
    start, end = span(text, col)
    if text[start - 1 : start] in "'\"" and end - start >= 2 and text[start - 1 : start] != "":
        start, end = start + 1, end - 1
    rng = lsp.Range(lsp.Position(line - 1, start - 1), lsp.Position(line - 1, end - 1))
    return rng, text[start - 1 : end - 1]


def nodes(doc: Document, lines: Sequence[str]) -> Iterator[Node]:
    """Every key and scalar value of the document, with its range."""
    for table, is_key in ((doc.keys, True), (doc.values, False)):
        for path, (line, col) in table.items():
            if not is_key and isinstance(_value(doc, path), dict | list):
                continue
            rng, text = name_range(lines, line, col)
            yield Node(path, is_key, text, rng)


def node_at(doc: Document, lines: Sequence[str], pos: lsp.Position) -> Node | None:
    """The key or scalar value under the cursor."""
    best: Node | None = None
    for node in nodes(doc, lines):
        r = node.range
        on_it = r.start.line == pos.line and r.start.character <= pos.character <= r.end.character
        if on_it and (best is None or r.start.character > best.range.start.character):
            best = node
    return best


def dotted_at(lines: Sequence[str], pos: lsp.Position) -> tuple[str, lsp.Range] | None:
    """The dotted name under the cursor (`vars.count`, `in.battery`), for expressions."""
    text = lines[pos.line] if pos.line < len(lines) else ""
    for match in _DOTTED.finditer(text):
        if match.start() <= pos.character <= match.end():
            rng = lsp.Range(lsp.Position(pos.line, match.start()), lsp.Position(pos.line, match.end()))
            return match.group(), rng
    return None


def value_at(doc: Document, path: Path_) -> object:
    return _value(doc, path)


def _value(doc: Document, path: Path_) -> object:
    data: object = doc.data
    for part in path:
        if isinstance(data, dict):
            data = data.get(part)
        elif isinstance(data, list) and isinstance(part, int) and 0 <= part < len(data):
            data = data[part]
        else:
            return None
    return data
