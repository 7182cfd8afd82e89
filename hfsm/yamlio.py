"""Read YAML 1.2 (core schema) into plain values, keeping the position of every key and value.

Why not a stock loader: PyYAML resolves YAML 1.1 (`on:` becomes True) and keeps the last of two
duplicate keys; both must be errors or strings here. libyaml parses; `hfsm.yamlbuild` builds the
values from its events, collecting every problem with its position. A file is read only when it
is a regular file of at most MAX_BYTES, so a FIFO, a device or a huge file is refused at once.
"""

from __future__ import annotations

import gc
import os
import re
import stat
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import yaml
from yaml import events as ev

from hfsm.errors import Finding, UserError
from hfsm.yamlbuild import MAX_DEPTH, MAX_EXPANDED, MAX_NODES, EventBuilder, Path_, Pos, TooBig
from hfsm.yamlhints import hint, unclosed

__all__ = ["MAX_BYTES", "MAX_DEPTH", "MAX_EXPANDED", "MAX_NODES", "Document", "Path_", "Pos"]

MAX_BYTES = 8 * 1024 * 1024


class _PyParser(yaml.reader.Reader, yaml.scanner.Scanner, yaml.parser.Parser):
    """The pure-Python pipeline, used when PyYAML was built without libyaml."""

    def __init__(self, text: str) -> None:
        yaml.reader.Reader.__init__(self, text)
        yaml.scanner.Scanner.__init__(self)
        yaml.parser.Parser.__init__(self)


def _parser_class() -> Any:
    try:
        from yaml._yaml import CParser
    except ImportError:  # PyYAML built without libyaml
        return _PyParser
    return CParser


_Parser: Any = _parser_class()


@dataclass
class Document:
    """Plain data read from one file, with where each key and value stood."""

    file: str
    data: Any
    keys: dict[Path_, Pos] = field(default_factory=dict)
    values: dict[Path_, Pos] = field(default_factory=dict)
    text: str = field(default="", repr=False)  # as read: to place a finding inside a string

    def pos(self, path: Path_, *, key: bool = False) -> Pos:
        """Position of the value (or key) at `path`, else of its nearest located ancestor."""
        table = self.keys if key else self.values
        for n in range(len(path), -1, -1):
            found = table.get(path[:n]) or (self.keys.get(path[:n]) if n else None)
            if found:
                return found
        return (1, 1)

    def finding(self, path: Path_, code: str, message: str, *, key: bool = False) -> Finding:
        line, col = self.pos(path, key=key)
        return Finding(self.file, line, col, code, message)


@contextmanager
def collector_paused() -> Iterator[None]:
    """Pause the cyclic garbage collector: reading creates many objects and no cycles to free."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def decode(raw: bytes, file: str) -> str:
    try:
        return raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as exc:
        before = raw[: exc.start]
        line = before.count(b"\n") + 1
        col = exc.start - (before.rfind(b"\n") + 1) + 1
        raise UserError(
            [Finding(file, line, col, "E104", f"the file is not UTF-8 (byte 0x{raw[exc.start]:02x})")]
        ) from None


def parse_text(text: str, file: str, *, kept: list[Finding] | None = None) -> Document:
    """Parse and build one YAML document; raise UserError with every problem found.

    With `kept`, the problems that leave a document to read (a duplicate key, a tag, a bad number)
    are added to it instead, and the document is returned as it was built around them."""
    doc = Document(file, None)
    builder = EventBuilder(file)
    cut = _flow_cut(text)
    parser = _Parser(text[:cut])
    try:
        with collector_paused():
            _drive(parser, builder, file)
        if cut < len(text):
            raise TooBig(_line_col(text, cut - 1), f"collections nested more than {MAX_DEPTH} deep")
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        deep = _too_deep(text, builder.block_depth(), mark.index if mark else len(text))
        if deep is None and cut < len(text):
            deep = _line_col(text, cut - 1)
        if deep is not None:
            message = f"collections nested more than {MAX_DEPTH} deep"
            raise UserError([Finding(file, *deep, "E106", message)]) from None
        opened = unclosed(exc, text.splitlines())
        if opened is not None:
            raise UserError([Finding(file, *opened)]) from None
        line, col = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        message = " ".join(str(p) for p in (exc.context, exc.problem) if p)
        extra = hint(message, text.splitlines(), line, col)
        message = f"YAML syntax: {message}" + (f"; {extra}" if extra else "")
        raise UserError([Finding(file, line, col, "E100", message)]) from None
    except yaml.reader.ReaderError as exc:
        line, col = _line_col(text, exc.position)
        char = exc.character if isinstance(exc.character, int) else ord(exc.character)
        message = f"the control character 0x{char:02x} is not allowed in YAML"
        raise UserError([Finding(file, line, col, "E100", message)]) from None
    except yaml.YAMLError as exc:
        message = " ".join(str(exc).split())
        raise UserError([Finding(file, 1, 1, "E100", f"YAML syntax: {message}")]) from None
    except TooBig as big:
        raise UserError([Finding(file, *big.pos, big.code, big.message)]) from None
    finally:
        parser.dispose()
    built = builder.built
    if builder.empty:
        raise UserError([Finding(file, 1, 1, "E105", "the file is empty")])
    if built.errors and kept is None:
        raise UserError(built.errors)
    if kept is not None:
        kept.extend(built.errors)
    doc.data, doc.keys, doc.values, doc.text = built.data, built.keys, built.values, text
    return doc


_FLOW = re.compile(
    r"(?<![^\s\[{,:])'[^']*+(?:''[^']*+)*+'"  # a single-quoted string (loops unrolled: a long one
    r'|(?<![^\s\[{,:])"[^"\\]*+(?:\\.[^"\\]*+)*+"'  # costs no backtracking), a double-quoted one
    r"|(?<!\S)#[^\n]*|[\[\]{}]"  # a comment, or a bracket
)


def _too_deep(text: str, blocks: int, end: int) -> Pos | None:
    """Where brackets nest past MAX_DEPTH (with `blocks` indented collections around them) before
    `end`: the parser's own nesting limit may be met first, but ours is the one reported."""
    index = _deep_bracket(text, MAX_DEPTH - blocks, end)
    return None if index is None else _line_col(text, index)


def _deep_bracket(text: str, limit: int, end: int) -> int | None:
    """The index of the first bracket that opens more than `limit` levels of brackets, before `end`
    (quoted strings and comments skipped)."""
    depth = 0
    for match in _FLOW.finditer(text, 0, min(end + 1, len(text))):
        char = match.group()
        if char in "[{":
            depth += 1
            if depth > limit:
                return match.start()
        elif char in "]}":
            depth = max(0, depth - 1)
    return None


def _flow_cut(text: str) -> int:
    """How much of `text` the parser is given: all of it, unless brackets alone nest past MAX_DEPTH;
    then up to that bracket, so that our limit meets it before any limit of the parser's own."""
    if text.count("[") + text.count("{") <= MAX_DEPTH:
        return len(text)
    index = _deep_bracket(text, MAX_DEPTH, len(text))
    return len(text) if index is None else index + 1


def _line_col(text: str, index: int) -> Pos:
    before = text[:index]
    return before.count("\n") + 1, index - (before.rfind("\n") + 1) + 1


def _drive(parser: Any, builder: EventBuilder, file: str) -> None:
    get = parser.get_event
    get()  # the stream's start
    if get().__class__ is ev.StreamEndEvent:
        builder.empty = True
        return
    builder.feed(get)
    get()  # the document's end
    after = get()
    if after.__class__ is not ev.StreamEndEvent:
        mark = after.start_mark
        message = "YAML syntax: a second document ('---'): a file holds one document"
        raise UserError([Finding(file, mark.line + 1, mark.column + 1, "E100", message)])


def read_file(path: Path) -> Document:
    file = str(path)
    return parse_text(decode(read_bytes(path, file), file), file)


def read_bytes(path: Path, file: str) -> bytes:
    """The bytes of a regular file of at most MAX_BYTES; never blocks on a FIFO or a device."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0))
    except OSError as exc:
        raise UserError([Finding(file, 1, 1, "E105", f"cannot read the file: {exc.strerror}")]) from None
    info = os.fstat(fd)
    if not stat.S_ISREG(info.st_mode):
        os.close(fd)
        kind = "a folder" if stat.S_ISDIR(info.st_mode) else "not a regular file (a FIFO, a device?)"
        raise UserError([Finding(file, 1, 1, "E105", f"cannot read the file: it is {kind}")])
    with os.fdopen(fd, "rb") as handle:
        if info.st_size > MAX_BYTES:
            raise UserError([_too_big(file, info.st_size)])
        try:
            raw = handle.read(MAX_BYTES + 1)
        except OSError as exc:
            raise UserError([Finding(file, 1, 1, "E105", f"cannot read the file: {exc.strerror}")]) from None
    if len(raw) > MAX_BYTES:
        raise UserError([_too_big(file, len(raw))])
    return raw


def _too_big(file: str, size: int) -> Finding:
    limit = MAX_BYTES // (1024 * 1024)
    message = f"the file is larger than {limit} MiB ({size:,} bytes): refused unread"
    return Finding(file, 1, 1, "E106", message)


class Parse(Protocol):
    def __call__(self, text: str, file: str, *, kept: list[Finding] | None = None) -> Document: ...


def read_mapping(
    path: Path,
    what: str,
    *,
    text: str | None = None,
    kept: list[Finding] | None = None,
    parse: Parse = parse_text,
) -> Document:
    """Read a file whose top level must be a mapping (`text`: its text, when it is not the disk's;
    `parse`: as `parse_text`, e.g. one that reads again only what changed)."""
    file = str(path)
    text = text if text is not None else decode(read_bytes(path, file), file)
    doc = parse(text, file, kept=kept)
    if not isinstance(doc.data, dict):
        kind = type(doc.data).__name__ if doc.data is not None else "null"
        raise UserError([doc.finding((), "E105", f"expected {what} (a mapping), got {kind}")])
    return doc
