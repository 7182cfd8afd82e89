"""Traces as values: JSON records written as the run goes (docs/REFERENCE.md#the-trace)."""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from json.encoder import c_make_encoder, encode_basestring  # type: ignore[attr-defined]
from pathlib import Path
from typing import IO, Any, Protocol

_iterencode: Any = (
    json.JSONEncoder(ensure_ascii=False, allow_nan=False, default=str, check_circular=False).iterencode
    if c_make_encoder is None  # a Python without the C accelerator
    else c_make_encoder(None, str, encode_basestring, None, ": ", ", ", False, False, False)
)  # markers, default, strings, indent, separators, sort_keys, skipkeys, allow_nan


def encode(value: Any) -> str:
    """`json.dumps(value, ensure_ascii=False, allow_nan=False, default=str)`, made by one encoder."""
    return "".join(_iterencode(value, 0))


class TraceSink(Protocol):
    def write(self, record: dict[str, Any]) -> None: ...

    def flush(self) -> None:
        """Called at the end of every tick that wrote something."""

    def close(self) -> None: ...


class ListTrace:
    """Keeps the records in memory: for tests and tools."""

    def __init__(self) -> None:
        self.records: list[dict[str, Any]] = []

    def write(self, record: dict[str, Any]) -> None:
        self.records.append(record)

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


class JsonlTrace:
    """One JSON object a line, written in whole lines: a crash leaves every line up to a tick's end.

    The bytes are `json.dumps(record, ensure_ascii=False, allow_nan=False, default=str)`'s. The
    encoder is made once (`json.dumps` makes one a call); a record's pieces are kept as it yields
    them, or as the text `write_line` is given (records the engine encoded itself, the same bytes:
    hfsm.runtime.records). At the end of a tick in which `JOIN_PIECES` are kept (few, so that they
    stay in the processor's cache), or every `_every` ticks, they are joined and written to the
    file's buffer; what the buffer holds is handed to the system once it holds `SAVE_CHARS`, or
    `SAVE_SECONDS` after the last time (a killed run loses about that much, never half a line).
    The clock is read only then: `_every` ticks are as many as lately took `LOOK_SHARE` of
    `SAVE_SECONDS` (1 to `LOOK_MOST`), since reading it took a tenth of a quick tick's trace.
    """

    SAVE_SECONDS = 0.25
    SAVE_CHARS = 1 << 18  # below the file's buffer, so that it never writes half a line itself
    JOIN_PIECES = 256
    LOOK_SHARE = 0.04
    LOOK_MOST = 64

    def __init__(self, path: Path) -> None:
        self.path = path
        self._file: IO[str] = path.open("w", encoding="utf-8", buffering=4 * self.SAVE_CHARS)
        self._pieces: list[str] = []
        self.write_line: Callable[[str], None] = self._pieces.append  # a line or more, each ended by "\n"
        self._unsaved = 0
        self._saved_at = self._looked_at = time.monotonic()
        self._every = self._due = 1  # ticks between looks at the clock, and until the next one

    def write(self, record: dict[str, Any]) -> None:
        pieces = self._pieces
        pieces.extend(_iterencode(record, 0))
        pieces.append("\n")

    def flush(self) -> None:
        """End of a tick: its lines are kept, written, and handed to the system, each when due."""
        self._due -= 1
        if self._due <= 0 or len(self._pieces) >= self.JOIN_PIECES:
            self._write()

    def _write(self, save: bool = False) -> None:
        if self._pieces:
            text = "".join(self._pieces)
            self._pieces.clear()
            self._file.write(text)
            self._unsaved += len(text)
        now = time.monotonic()
        ticks = self._every - self._due
        if ticks > 0:
            took = now - self._looked_at
            every = int(self.SAVE_SECONDS * self.LOOK_SHARE * ticks / took) if took > 0 else self.LOOK_MOST
            self._every = self._due = max(1, min(self.LOOK_MOST, every))
            self._looked_at = now
        if save or self._unsaved >= self.SAVE_CHARS or now - self._saved_at >= self.SAVE_SECONDS:
            self._file.flush()
            self._unsaved = 0
            self._saved_at = now

    def close(self) -> None:
        self._write(save=True)
        self._file.close()


RECORD_SHAPE = ("an object with a time 't', a 'kind', an 'agent' (null for the run's own) "
                "and a 'path' of names")


def is_record(record: object) -> bool:
    """Whether `record` has the shape of what `hfsm-run --trace` writes (RECORD_SHAPE)."""
    if not isinstance(record, dict):
        return False
    path, t, agent = record.get("path"), record.get("t"), record.get("agent", "")
    return (isinstance(path, list) and all(isinstance(p, str) for p in path)
            and isinstance(t, int | float) and not isinstance(t, bool)
            and isinstance(record.get("kind"), str)
            and (agent is None or isinstance(agent, str)))


def read_jsonl(path: Path) -> list[dict[str, Any]]:
    with path.open(encoding="utf-8") as f:
        return [json_line(line) for line in f if line.strip()]


def _no_constant(name: str) -> Any:
    raise ValueError(f"{name} is not a number JSON allows")


def json_line(line: str) -> Any:
    """One line of a JSON-lines file; ValueError for anything that is not plain JSON (NaN, a number
    of more digits than Python converts, nesting deeper than the interpreter's recursion)."""
    try:
        return json.loads(line, parse_constant=_no_constant)
    except RecursionError:
        raise ValueError("nested too deep") from None
