"""The records a page shows: what a finished trace holds, or what a live run has written so far."""

from __future__ import annotations

import queue
from typing import Any

Record = dict[str, Any]
QUEUE_SIZE = 100_000


class Hub:
    """All records so far, in order, for any number of pages; fed from a trace or a live run.

    A live run writes through `MonitorSink` into a bounded queue and never waits: when the queue is
    full (nothing drains it), the record is counted in `dropped` and the run goes on unchanged.
    """

    def __init__(
        self, records: list[Record] | None = None, *, live: bool = False, size: int = QUEUE_SIZE
    ) -> None:
        self.records: list[Record] = list(records or [])
        self.live = live
        self.ended = not live
        self.dropped = 0
        self.video_ready = True  # whether its video (if any) is written: a live run's, once the world closed
        self._queue: queue.Queue[Record | None] = queue.Queue(size)

    def offer(self, record: Record | None) -> None:
        """From the run's thread: a record, or None when the run has ended. Never blocks."""
        try:
            self._queue.put_nowait(record)
        except queue.Full:
            self.dropped += 1

    def drain(self) -> int:
        """Move queued records into `records` (the server's thread); how many came."""
        came = 0
        while True:
            try:
                record = self._queue.get_nowait()
            except queue.Empty:
                break
            if record is None:
                self.ended = True
            else:
                self.records.append(record)
                came += 1
        return came

    def since(self, start: int) -> list[Record]:
        self.drain()
        return self.records[start:]


class MonitorSink:
    """A trace sink (hfsm.trace.TraceSink) that hands each record to a hub."""

    def __init__(self, hub: Hub) -> None:
        self.hub = hub

    def write(self, record: Record) -> None:
        self.hub.offer(record)

    def flush(self) -> None:
        pass

    def close(self) -> None:
        self.hub.offer(None)
