"""Read YAML 1.2 (core schema) into plain values, keeping the position of every key and value.

Why not a stock loader: PyYAML resolves YAML 1.1 (`on:` becomes True) and keeps the last of two
duplicate keys; both must be errors or strings here. We let libyaml compose the node graph with a
core-schema resolver, then build the values ourselves, collecting every problem with its position.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml
from yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

from hfsm.errors import Finding, UserError

Path_ = tuple[str | int, ...]
Pos = tuple[int, int]
MAX_NODES = 200_000
CORE = "tag:yaml.org,2002:"


class _CoreResolver(yaml.resolver.BaseResolver):
    """The YAML 1.2 core schema's implicit types, nothing else."""


for _tag, _regex, _first in (
    ("bool", r"^(?:true|True|TRUE|false|False|FALSE)$", "tTfF"),
    ("null", r"^(?:~|null|Null|NULL|)$", ["~", "n", "N", ""]),
    ("int", r"^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$", "-+0123456789"),
    (
        "float",
        r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?"
        r"|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$",
        "-+0123456789.",
    ),
):
    _CoreResolver.add_implicit_resolver(CORE + _tag, re.compile(_regex), list(_first))


class _PyParser(yaml.reader.Reader, yaml.scanner.Scanner, yaml.parser.Parser, yaml.composer.Composer):
    """The pure-Python pipeline, used when PyYAML was built without libyaml."""

    def __init__(self, text: str) -> None:
        yaml.reader.Reader.__init__(self, text)
        yaml.scanner.Scanner.__init__(self)
        yaml.parser.Parser.__init__(self)
        yaml.composer.Composer.__init__(self)


def _parser_class() -> type:
    try:
        from yaml._yaml import CParser
    except ImportError:  # PyYAML built without libyaml
        return _PyParser
    return CParser


_Parser: Any = _parser_class()


class _Composer(_Parser, _CoreResolver):  # type: ignore[misc]
    def __init__(self, text: str) -> None:
        _Parser.__init__(self, text)
        _CoreResolver.__init__(self)


@dataclass
class Document:
    """Plain data read from one file, with where each key and value stood."""

    file: str
    data: Any
    keys: dict[Path_, Pos] = field(default_factory=dict)
    values: dict[Path_, Pos] = field(default_factory=dict)

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


def _mark(node: Node) -> Pos:
    return (node.start_mark.line + 1, node.start_mark.column + 1)


class _Builder:
    def __init__(self, doc: Document) -> None:
        self.doc = doc
        self.errors: list[Finding] = []
        self.count = 0

    def error(self, node: Node, code: str, message: str) -> None:
        line, col = _mark(node)
        self.errors.append(Finding(self.doc.file, line, col, code, message))

    def build(self, node: Node, path: Path_) -> Any:
        self.count += 1
        if self.count > MAX_NODES:
            raise _TooBig(node)
        self.doc.values.setdefault(path, _mark(node))
        if isinstance(node, ScalarNode):
            return self.scalar(node)
        if isinstance(node, SequenceNode):
            self.check_tag(node, "seq")
            return [self.build(item, (*path, i)) for i, item in enumerate(node.value)]
        assert isinstance(node, MappingNode)
        self.check_tag(node, "map")
        return self.mapping(node, path)

    def check_tag(self, node: Node, kind: str) -> bool:
        if node.tag == CORE + kind:
            return True
        self.error(node, "E102", f"tag '{node.tag}' is not allowed: machine files take plain YAML")
        return False

    def mapping(self, node: MappingNode, path: Path_) -> dict[Any, Any]:
        out: dict[Any, Any] = {}
        for key_node, value_node in node.value:
            if not isinstance(key_node, ScalarNode):
                self.error(key_node, "E100", "a key must be a plain scalar, not a list or mapping")
                continue
            if key_node.tag == CORE + "merge" or (key_node.value == "<<" and not key_node.style):
                self.error(key_node, "E103", "merge keys ('<<') are not allowed")
                continue
            key = self.scalar(key_node)
            if key in out:
                self.error(key_node, "E101", f"duplicate key '{key}'")
                continue
            self.doc.keys[(*path, key)] = _mark(key_node)
            out[key] = self.build(value_node, (*path, key))
        return out

    def scalar(self, node: ScalarNode) -> Any:
        text = node.value
        kind = node.tag.removeprefix(CORE)
        try:
            return _SCALARS[kind](text)
        except KeyError:
            self.check_tag(node, "str")
        except ValueError:
            self.error(node, "E100", f"'{text}' is not a valid {kind}")
        return text


def _int(text: str) -> int:
    if text.startswith(("0o", "0x")):
        return int(text[2:], 8 if text[1] == "o" else 16)
    return int(text)


def _float(text: str) -> float:
    lowered = text.lower()
    if lowered.endswith(".inf"):
        return -math.inf if lowered.startswith("-") else math.inf
    if lowered == ".nan":
        return math.nan
    return float(text)


def _bool(text: str) -> bool:
    if text.lower() not in ("true", "false"):
        raise ValueError(text)
    return text.lower() == "true"


def _null(text: str) -> None:
    if text not in ("", "~", "null", "Null", "NULL"):
        raise ValueError(text)


_SCALARS: dict[str, Any] = {"str": str, "int": _int, "float": _float, "bool": _bool, "null": _null}


class _TooBig(Exception):
    def __init__(self, node: Node) -> None:
        self.node = node


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


def parse_text(text: str, file: str) -> Document:
    """Compose and build one YAML document; raise UserError with every problem found."""
    doc = Document(file, None)
    try:
        composer = _Composer(text)
        try:
            node = composer.get_single_node()
        finally:
            composer.dispose()
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line, col = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        message = " ".join(str(p) for p in (exc.context, exc.problem) if p)
        raise UserError([Finding(file, line, col, "E100", f"YAML syntax: {message}")]) from None
    except yaml.YAMLError as exc:
        raise UserError([Finding(file, 1, 1, "E100", f"YAML syntax: {exc}")]) from None
    if node is None:
        raise UserError([Finding(file, 1, 1, "E105", "the file is empty")])
    builder = _Builder(doc)
    try:
        doc.data = builder.build(node, ())
    except _TooBig as big:
        line, col = _mark(big.node)
        message = f"the document expands to more than {MAX_NODES} nodes (aliases nested too deep?)"
        raise UserError([Finding(file, line, col, "E106", message)]) from None
    if builder.errors:
        raise UserError(builder.errors)
    return doc


def read_file(path: Path) -> Document:
    file = str(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise UserError([Finding(file, 1, 1, "E105", f"cannot read the file: {exc.strerror}")]) from None
    return parse_text(decode(raw, file), file)


def read_mapping(path: Path, what: str) -> Document:
    """Read a file whose top level must be a mapping."""
    doc = read_file(path)
    if not isinstance(doc.data, dict):
        kind = type(doc.data).__name__ if doc.data is not None else "null"
        raise UserError([doc.finding((), "E105", f"expected {what} (a mapping), got {kind}")])
    return doc
