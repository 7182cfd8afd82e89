"""The records a page shows: what a finished trace holds, or what a live run has written so far."""

from __future__ import annotations

import json
from collections import deque
from typing import Any

from hfsm.trace import Lines

Record = dict[str, Any]
Item = Record | str  # a record, or its JSON text as the run's trace has it (never encoded again)
QUEUE_SIZE = 100_000


class Hub:
    """All records so far, in order, for any number of pages; fed from a trace or a live run.

    A live run writes through `MonitorSink` into a bounded queue and never waits: when the queue is
    full (nothing drains it), the record is counted in `dropped` and the run goes on unchanged. The
    queue is a deque (appends and pops are atomic in CPython): no lock taken for each record.
    """

    def __init__(
        self, records: list[Record] | None = None, *, live: bool = False, size: int = QUEUE_SIZE
    ) -> None:
        self.records: list[Item] = list(records or [])
        self.live = live
        self.ended = not live
        self.dropped = 0
        self.video_ready = True  # whether its video (if any) is written: a live run's, once the world closed
        self._queue: deque[Item | None] = deque()
        self._size = size

    def offer(self, record: Item | None) -> None:
        """From the run's thread: a record, or None when the run has ended. Never blocks."""
        if record is not None and len(self._queue) >= self._size:
            self.dropped += 1
        else:
            self._queue.append(record)

    def drain(self) -> int:
        """Move queued records into `records` (the server's thread); how many came."""
        came = 0
        while self._queue:
            record = self._queue.popleft()
            if record is None:
                self.ended = True
            else:
                self.records.append(record)
                came += 1
        return came

    def since(self, start: int) -> list[Record]:
        self.drain()
        return [json.loads(r) if isinstance(r, str) else r for r in self.records[start:]]

    def since_json(self, start: int) -> tuple[bytes, int]:
        """The records from `start` as a JSON array, UTF-8 (a lone surrogate as its escape), and how
        many: the lines of a live run's trace go as they are."""
        self.drain()
        batch = self.records[start:]
        text = ",".join(r if isinstance(r, str) else json.dumps(r, default=str) for r in batch)
        return f"[{text}]".encode("utf-8", "backslashreplace"), len(batch)


class MonitorSink:
    """A trace sink (hfsm.trace.TraceSink) that hands each record to a hub."""

    def __init__(self, hub: Hub) -> None:
        self.hub = hub
        self._lines = Lines()

    def write(self, record: Record) -> None:
        self.hub.offer(record)

    def write_line(self, text: str) -> None:
        for line in self._lines.feed(text):
            self.hub.offer(line)

    def flush(self) -> None:
        pass

    def close(self) -> None:
        self.hub.offer(None)
