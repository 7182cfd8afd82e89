"""Traces as values: JSON records written as the run goes (SPEC section 10)."""

from __future__ import annotations

import json
import time
from json.encoder import c_make_encoder, encode_basestring  # type: ignore[attr-defined]
from pathlib import Path
from typing import IO, Any, Protocol


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
    them; at the end of a tick they are joined and written in one call, and handed to the system
    at most `SAVE_SECONDS` later (a killed run loses at most that much, never half a line).
    """

    SAVE_SECONDS = 0.25
    SAVE_CHARS = 1 << 18  # below the file's buffer, so that it never writes half a line itself

    def __init__(self, path: Path) -> None:
        self.path = path
        self._file: IO[str] = path.open("w", encoding="utf-8", buffering=4 * self.SAVE_CHARS)
        self._pieces: list[str] = []
        self._unsaved = 0
        self._saved_at = time.monotonic()
        if c_make_encoder is None:  # a Python without the C accelerator
            encoder = json.JSONEncoder(ensure_ascii=False, allow_nan=False, default=str, check_circular=False)
            self._iterencode: Any = lambda record, _: encoder.iterencode(record)
        else:
            self._iterencode = c_make_encoder(
                None, str, encode_basestring, None, ": ", ", ", False, False, False
            )  # markers, default, strings, indent, separators, sort_keys, skipkeys, allow_nan

    def write(self, record: dict[str, Any]) -> None:
        pieces = self._pieces
        pieces.extend(self._iterencode(record, 0))
        pieces.append("\n")

    def flush(self) -> None:
        """End of a tick: its lines go to the file, and to the system when due."""
        if self._pieces:
            text = "".join(self._pieces)
            self._pieces.clear()
            self._file.write(text)
            self._unsaved += len(text)
        now = time.monotonic()
        if self._unsaved and (self._unsaved >= self.SAVE_CHARS or now - self._saved_at >= self.SAVE_SECONDS):
            self._save(now)

    def _save(self, now: float) -> None:
        self._file.flush()
        self._unsaved = 0
        self._saved_at = now

    def close(self) -> None:
        self.flush()
        self._save(time.monotonic())
        self._file.close()


def read_jsonl(path: Path) -> list[dict[str, Any]]:
    with path.open(encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]
