"""Traces as values: JSON records written as the run goes (SPEC section 10)."""

from __future__ import annotations

import json
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
    """One JSON object a line, flushed at the end of every tick: a crash leaves whole lines up to it."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._file: IO[str] = path.open("w", encoding="utf-8")
        self._encode = json.JSONEncoder(ensure_ascii=False, allow_nan=False, default=str).encode

    def write(self, record: dict[str, Any]) -> None:
        self._file.write(self._encode(record) + "\n")

    def flush(self) -> None:
        self._file.flush()

    def close(self) -> None:
        self._file.close()


def read_jsonl(path: Path) -> list[dict[str, Any]]:
    with path.open(encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]
