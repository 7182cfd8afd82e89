"""Reading a changed document again from the state that changed, not from the whole text.

An editor sends the whole text on every change, and most changes fall inside one state. When the
new text differs from the last one read well only inside one state's lines (the lines from its key
to the next state's, under `states:`), that state alone is parsed, and the last document is mended
with it: its data, and the positions of every key and value, those below moved by the lines added
or taken away. Anything less plain is read whole, as `hfsm-run --check` reads it: a text with
problems (before or after), tabs, carriage returns, an anchor in the changed state,
states added, removed or renamed to another's name, or a `states:` not written as an indented block.
The result is the document a whole reading gives (a property test holds it to that).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from hfsm.errors import Finding, UserError
from hfsm.yamlio import Document, Path_, Pos, parse_text

_STATE = re.compile(r"[a-z][a-z0-9_]*:(?: |$)")
_ANCHOR = "&"  # an anchor in the changed state may be aliased in another: read whole then


@dataclass(frozen=True)
class _Split:
    lines: list[str]
    chunks: list[tuple[int, int]]  # each state's lines, [start, end), 0-based
    end: int  # the line after the states


@dataclass(frozen=True)
class _Read:
    text: str
    doc: Document
    split: _Split


def split(text: str) -> _Split | None:
    """The states' lines of a text whose `states:` is an indented block of plain keys; else None."""
    if "\t" in text or "\r" in text:
        return None
    lines = text.split("\n")
    starts = [i for i, line in enumerate(lines) if line.rstrip() == "states:"]
    if len(starts) != 1:
        return None
    indent, chunks, end = -1, [], len(lines)
    for i in range(starts[0] + 1, len(lines)):
        line = lines[i]
        body = line.lstrip(" ")
        if not body or body.startswith("#"):
            continue
        column = len(line) - len(body)
        if column == 0:
            end = i
            break
        if indent < 0:
            indent = column
        if column < indent or (column == indent and not _STATE.match(body)):
            return None
        if column == indent:
            chunks.append(i)
    if not chunks:
        return None
    bounds = [(a, b) for a, b in zip(chunks, [*chunks[1:], end], strict=True)]
    return _Split(lines, bounds, end)


class Reparser:
    """Each file's last text read without problems, and its document: the start of the next."""

    def __init__(self) -> None:
        self._last: dict[str, _Read] = {}

    def parse(self, text: str, file: str, *, kept: list[Finding] | None = None) -> Document:
        """As `hfsm.yamlio.parse_text`."""
        last = self._last.get(file)
        if last is not None and last.text == text:
            return last.doc
        mended = _mend(last, text, file) if last is not None else None
        if mended is not None:
            self._last[file] = mended
            return mended.doc
        problems: list[Finding] = []
        try:
            doc = parse_text(text, file, kept=problems)
        except UserError:
            self._last.pop(file, None)
            raise
        if kept is not None:
            kept.extend(problems)
        elif problems:
            raise UserError(problems)
        found = split(text) if not problems and isinstance(doc.data, dict) else None
        if found is not None and _fits(doc, found):
            self._last[file] = _Read(text, doc, found)
        else:
            self._last.pop(file, None)
        return doc


def _fits(doc: Document, found: _Split) -> bool:
    states = doc.data.get("states")
    return isinstance(states, dict) and len(states) == len(found.chunks)


def _mend(last: _Read, text: str, file: str) -> _Read | None:
    new = split(text)
    old = last.split
    if new is None or len(new.chunks) != len(old.chunks) or new.chunks[0][0] != old.chunks[0][0]:
        return None
    if new.lines[: new.chunks[0][0]] != old.lines[: old.chunks[0][0]]:
        return None
    if new.lines[new.end :] != old.lines[old.end :]:
        return None
    changed = [
        k
        for k, ((a, b), (c, d)) in enumerate(zip(old.chunks, new.chunks, strict=True))
        if old.lines[a:b] != new.lines[c:d]
    ]
    if len(changed) != 1:
        return None
    k = changed[0]
    (a, b), (_, d) = old.chunks[k], new.chunks[k]
    before, after = "\n".join(old.lines[a:b]), "\n".join(new.lines[a:d])
    if _ANCHOR in before or _ANCHOR in after:
        return None
    part = _parse_part(after, file)
    if part is None:
        return None
    states = last.doc.data["states"]
    names = list(states)
    name = next(iter(part.data))
    if name != names[k] and name in states:
        return None
    doc = _merged(last.doc, part, names[k], name, (a, b, d - b), text)
    return _Read(text, doc, new)


def _parse_part(text: str, file: str) -> Document | None:
    problems: list[Finding] = []
    try:
        part = parse_text(text, file, kept=problems)
    except UserError:
        return None
    if problems or not isinstance(part.data, dict) or len(part.data) != 1:
        return None
    return part


def _merged(
    doc: Document, part: Document, old: str, new: str, lines: tuple[int, int, int], text: str
) -> Document:
    """`doc` with state `old` replaced by `part`'s state `new`; `lines`: the old state's lines
    [a, b) (0-based) and how many lines the new one adds."""
    a, b, delta = lines
    data = dict(doc.data)
    data["states"] = {
        (new if n == old else n): (part.data[new] if n == old else v) for n, v in doc.data["states"].items()
    }
    keys = _table(doc.keys, part.keys, a, b, delta, key=True)
    values = _table(doc.values, part.values, a, b, delta, key=False)
    return Document(doc.file, data, keys, values, text)


def _table(
    old: dict[Path_, Pos], part: dict[Path_, Pos], a: int, b: int, delta: int, *, key: bool
) -> dict[Path_, Pos]:
    """The positions of the old table, those of the changed state's lines replaced by the part's
    (moved down to where it stands), those below it moved by `delta` lines, in the text's order."""
    mine = {
        (("states", *path) if path else ("states",)): (line + a, col) for path, (line, col) in part.items()
    }
    whole = old.get(("states",))
    if key or whole is None or not a < whole[0] <= b:
        mine.pop(("states",), None)  # where the states' mapping starts: another state's line
    out: dict[Path_, Pos] = {}
    placed = False
    for path, (line, col) in old.items():
        if a < line <= b:
            if not placed:
                out.update(mine)
                placed = True
            continue
        out[path] = (line + delta, col) if line > b else (line, col)
    if not placed:
        out.update(mine)
    return out
