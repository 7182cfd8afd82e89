"""Build plain values straight from libyaml's event stream, in one pass and without recursion.

Composing a node graph first (PyYAML's composer) costs a Python call per node to resolve its tag,
recurses in C (a file nested 100,000 deep crashes the process) and leaves a graph for the garbage
collector to walk. Here an explicit stack bounds the depth, an alias replays the events of its
anchor (each replayed node counted, so an alias bomb stops early) and every key and value keeps
its position.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from yaml import events as ev

from hfsm.errors import Finding
from hfsm.yamlscalars import CONVERT, CONVERT_ME, CORE, NOT_VALID, PlainScalars, implicit_kind

Path_ = tuple[str | int, ...]
Pos = tuple[int, int]
MAX_DEPTH = 100  # nested collections
MAX_NODES = 1_000_000  # scalars and collections in one file, keys included
MAX_EXPANDED = 100_000  # nodes that aliases add by repeating their anchors


class TooBig(Exception):
    """The document passes a limit: stop at once, at this position."""

    def __init__(self, pos: Pos, message: str, code: str = "E106") -> None:
        super().__init__(message)
        self.pos = pos
        self.message = message
        self.code = code


_NO_KEY: Any = object()  # a mapping waits for its next key
_BAD_KEY: Any = object()  # the key was refused: build the value, then drop it


@dataclass(slots=True)
class _Frame:
    value: Any  # the dict or list being filled
    path: Path_
    is_list: bool
    key: Any = _NO_KEY
    anchor: str | None = None
    log_start: int = 0
    flow: bool = False  # written [ ] or { }


@dataclass
class Built:
    data: Any = None
    keys: dict[Path_, Pos] = field(default_factory=dict)
    values: dict[Path_, Pos] = field(default_factory=dict)
    errors: list[Finding] = field(default_factory=list)


@dataclass(frozen=True, slots=True)
class _Ref:
    """An alias recorded inside an anchor: the span of `log` it repeats."""

    start: int
    end: int


def _pos(event: Any) -> Pos:
    mark = event.start_mark
    return (mark.line + 1, mark.column + 1)


_SCALAR, _ALIAS = ev.ScalarEvent, ev.AliasEvent
_MAP_START, _SEQ_START = ev.MappingStartEvent, ev.SequenceStartEvent
_ENDS = (ev.MappingEndEvent, ev.SequenceEndEvent)


class EventBuilder:
    """`feed` it the parser's events of one document, then read `built`."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.built = Built()
        self.stack: list[_Frame] = []
        self.nodes = 0
        self.expanded = 0
        self.anchors: dict[str, _Ref] = {}
        self.log: list[Any] = []  # events (and _Refs) inside anchors, kept for their aliases
        self.recording = 0  # anchored collections open now
        self.done = False
        self.alias_pos: Pos = (1, 1)  # of the alias being replayed
        self._plain = PlainScalars()
        self.empty = False  # the stream holds no document

    def error(self, pos: Pos, code: str, message: str) -> None:
        self.built.errors.append(Finding(self.file, pos[0], pos[1], code, message))

    def feed(self, get: Callable[[], Any]) -> None:
        """Build the root node from `get()`, the parser's next event."""
        pending: list[Iterator[int]] = []  # aliases being replayed: indices into `log`
        stack = self.stack
        while not self.done:
            if pending or self.recording or not stack:
                event = self._next(get, pending)
            else:
                event = get()
                if self._plain_value(event):
                    continue
                event = self._take(event, pending)
            if event is not None:
                self._build(event, bool(pending))

    def _plain_value(self, event: Any) -> bool:
        """The common case, in one place for speed: a plain scalar in a list or as a mapping's value."""
        if event.__class__ is not _SCALAR or event.tag is not None or event.anchor is not None:
            return False
        parent = self.stack[-1]
        if not parent.is_list and parent.key is _NO_KEY:
            return False
        self.nodes += 1
        mark: Any = event.start_mark
        pos = (mark.line + 1, mark.column + 1)
        if self.nodes > MAX_NODES:
            raise TooBig(pos, f"the document has more than {MAX_NODES:,} nodes")
        text = event.value
        value = self._plain[text] if event.implicit[0] else text
        if value is CONVERT_ME:
            value = self._scalar(event, pos)
        if parent.is_list:
            path = (*parent.path, len(parent.value))
            parent.value.append(value)
        else:
            key, parent.key = parent.key, _NO_KEY
            if key is _BAD_KEY:
                return True
            path = (*parent.path, key)
            parent.value[key] = value
        self.built.values[path] = pos
        return True

    def _build(self, event: Any, replay: bool) -> None:
        cls = event.__class__
        if cls in _ENDS:
            self._end(replay)
            return
        mark = event.start_mark
        pos = (mark.line + 1, mark.column + 1)
        self.nodes += 1
        if self.nodes > MAX_NODES:
            raise TooBig(pos, f"the document has more than {MAX_NODES:,} nodes")
        if cls is _SCALAR:
            value = self._scalar(event, pos)
            if event.anchor is not None and not replay:
                self.anchors[event.anchor] = _Ref(len(self.log) - 1, len(self.log))
            self._place(event, value, pos)
            return
        value = self._collection(event, cls is _MAP_START, pos)
        frame = _Frame(value, self._place(event, value, pos), cls is _SEQ_START, flow=bool(event.flow_style))
        if event.anchor is not None and not replay:
            frame.anchor, frame.log_start = event.anchor, len(self.log) - 1
            self.recording += 1
        self.stack.append(frame)

    def _next(self, get: Callable[[], Any], pending: list[Iterator[int]]) -> Any:
        """The next event to build, from a replay under way or from the parser; None: look again."""
        if pending:
            i = next(pending[-1], None)
            if i is None:
                pending.pop()
                return None
            event: Any = self.log[i]
            self.expanded += 1
            if self.expanded > MAX_EXPANDED:
                message = f"aliases expand to more than {MAX_EXPANDED:,} nodes (an alias bomb?)"
                raise TooBig(self.alias_pos, message)
            if event.__class__ is _Ref:
                pending.append(iter(range(event.start, event.end)))
                return None
            return event
        return self._take(get(), pending)

    def _take(self, event: Any, pending: list[Iterator[int]]) -> Any:
        """An event from the parser: an alias starts a replay (None), an anchored one is logged."""
        if event.__class__ is _ALIAS:
            self.alias_pos = _pos(event)
            ref = self.anchors.get(event.anchor or "")
            if ref is None:
                message = f"alias '*{event.anchor}' names no anchor defined before it"
                raise TooBig(self.alias_pos, message, "E100")
            if self.recording:
                self.log.append(ref)
            pending.append(iter(range(ref.start, ref.end)))
            return None
        if self.recording or (event.__class__ not in _ENDS and event.anchor is not None):
            self.log.append(event)
        return event

    def _place(self, event: Any, value: Any, pos: Pos) -> Path_:
        """Put a scalar or a new collection in its parent; return its path."""
        stack = self.stack
        if not stack:
            self.built.data = value
            self.built.values[()] = pos
            self.done = event.__class__ is _SCALAR
            return ()
        parent = stack[-1]
        if parent.is_list:
            path: Path_ = (*parent.path, len(parent.value))
            parent.value.append(value)
        elif parent.key is _NO_KEY:
            parent.key = self._key(event, value, parent, pos)
            return (*parent.path, "?")
        else:
            key, parent.key = parent.key, _NO_KEY
            if key is _BAD_KEY:
                return (*parent.path, "?")
            path = (*parent.path, key)
            parent.value[key] = value
        self.built.values[path] = pos
        return path

    def _end(self, replay: bool) -> None:
        frame = self.stack.pop()
        if frame.anchor is not None and not replay:
            self.recording -= 1
            self.anchors[frame.anchor] = _Ref(frame.log_start, len(self.log))
        if not self.stack:
            self.done = True

    def block_depth(self) -> int:
        """Collections open now that are written as blocks (indented), not in brackets."""
        return sum(not frame.flow for frame in self.stack)

    def _collection(self, event: Any, is_map: bool, pos: Pos) -> dict[Any, Any] | list[Any]:
        if len(self.stack) >= MAX_DEPTH:
            raise TooBig(pos, f"collections nested more than {MAX_DEPTH} deep")
        tag = event.tag
        if tag is not None and tag != "!" and tag != CORE + ("map" if is_map else "seq"):
            self.error(pos, "E102", f"tag '{tag}' is not allowed: machine files take plain YAML")
        return {} if is_map else []

    def _scalar(self, event: Any, pos: Pos) -> Any:
        text: str = event.value
        tag = event.tag
        if tag is None or tag == "!":
            if not event.implicit[0]:
                return text
            if not text:
                return None
            kind = implicit_kind(text)
            if kind is None:
                return text
        elif tag.startswith(CORE) and tag[len(CORE) :] in CONVERT:
            kind = tag[len(CORE) :]
        else:
            self.error(pos, "E102", f"tag '{tag}' is not allowed: machine files take plain YAML")
            return text
        try:
            return CONVERT[kind](text)
        except ValueError:
            self.error(pos, "E100", f"'{text}' {NOT_VALID.get(kind, f'is not a valid {kind}')}")
        return text

    def _key(self, event: Any, key: Any, parent: _Frame, pos: Pos) -> Any:
        if event.__class__ is not _SCALAR:
            self.error(pos, "E100", "a key must be a plain scalar, not a list or mapping")
            return _BAD_KEY
        if event.tag == CORE + "merge" or (event.value == "<<" and not event.style):
            self.error(pos, "E103", "merge keys ('<<') are not allowed")
            return _BAD_KEY
        if not isinstance(key, str):
            self.error(pos, "E100", f"a key must be a string, not {_kind(key)} {event.value}; "
                       f"write '{event.value}' in quotes if text was meant")
            return _BAD_KEY
        if key in parent.value:
            self.error(pos, "E101", f"duplicate key '{key}'")
            return _BAD_KEY
        self.built.keys[(*parent.path, key)] = pos
        return key


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    return {bool: "the boolean", int: "the integer", float: "the number"}.get(type(value), "the value")
