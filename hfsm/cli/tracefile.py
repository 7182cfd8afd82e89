"""The trace file of `hfsm-run`: like JsonlTrace, but a failed write (a full disk) ends the run with
a clear error, and the file keeps the whole lines written before it."""

from __future__ import annotations

import contextlib
import json
import math
import os
from pathlib import Path
from typing import IO, Any

from hfsm.errors import UsageError
from hfsm.runtime.core import FatalError

_encode = json.JSONEncoder(ensure_ascii=False, allow_nan=False, default=str).encode


def _finite(value: Any) -> Any:
    """Non-finite floats as text, so that every line stays JSON."""
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_finite(v) for v in value]
    return value


class TraceFile:
    def __init__(self, path: Path) -> None:
        self.path = path
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            self._file: IO[str] = path.open("w", encoding="utf-8")
        except OSError as exc:
            raise UsageError(f"--trace: cannot write {path}: {exc.strerror or exc}") from None
        self._good = 0  # bytes known to be on disk: whole lines
        self.failed: str | None = None
        self._reported = False

    def write(self, record: dict[str, Any]) -> None:
        if self.failed:
            return
        try:
            line = _encode(record)
        except ValueError:
            line = _encode(_finite(record))
        self.write_line(line + "\n")

    def write_line(self, line: str) -> None:
        """Records already encoded as `write` would, each ended by a newline (hfsm.runtime.records)."""
        if self.failed:
            return
        try:
            self._file.write(line)
        except OSError as exc:
            self._fail(exc)

    def flush(self) -> None:
        """At the end of every tick; raises FatalError once, at the first tick a write failed."""
        if not self.failed:
            try:
                self._file.flush()
                self._good = self._file.tell()
            except OSError as exc:
                self._fail(exc)
        if self.failed and not self._reported:
            self._reported = True
            raise FatalError("", self.failed)

    def close(self) -> None:
        try:
            if not self.failed:
                self._file.flush()
        except OSError as exc:
            self._fail(exc)
        with contextlib.suppress(OSError):  # the buffer could not be written: cut back below
            self._file.close()
        if self.failed:
            self._cut_back()

    def _fail(self, exc: OSError) -> None:
        self.failed = f"--trace: cannot write {self.path}: {exc.strerror or exc}"

    def _cut_back(self) -> None:
        """Leave only the whole lines written before the failure."""
        with contextlib.suppress(OSError):
            if self.path.is_file() and self.path.stat().st_size > self._good:
                os.truncate(self.path, self._good)
