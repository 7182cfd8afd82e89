"""Radio between robots: fixed latency, seeded independent loss, deterministic delivery order."""

from __future__ import annotations

import heapq
import itertools
from collections import Counter
from typing import Any

import numpy as np

BROADCAST = "*"
Message = tuple[str, str, Any]


class Radio:
    """`send` queues a message stamped with its send time; `deliver(t)` returns, in order of
    arrival time and then send order, every message with send time + latency <= t. A lost
    message (probability `loss`, decided at send time from `seed`) never arrives. `to` may be
    a robot name or BROADCAST ("*"); the receiver filters by `to`."""

    def __init__(self, latency_s: float = 0.1, loss: float = 0.0, seed: int = 0) -> None:
        if latency_s < 0.0 or not 0.0 <= loss <= 1.0:
            raise ValueError("latency must be >= 0 and loss in [0, 1]")
        self.latency_s = latency_s
        self.loss = loss
        self._rng = np.random.default_rng([seed, 0x4AD10])
        self._queue: list[tuple[float, int, Message]] = []
        self._counter = itertools.count()
        self.sent = 0
        self.lost = 0
        self._silent: set[str] = set()
        self._read: Counter[str] = Counter()

    def silence(self, name: str) -> None:
        """A robot that failed: from now on it sends nothing and hears nothing."""
        self._silent.add(name)

    def send(self, sender: str, to: str, payload: Any, t: float) -> bool:
        """Queue a message sent at time t; returns False if it will be lost."""
        self.sent += 1
        if sender in self._silent:
            self.lost += 1
            return False
        if self.loss > 0.0 and float(self._rng.random()) < self.loss:
            self.lost += 1
            return False
        heapq.heappush(self._queue, (t + self.latency_s, next(self._counter), (sender, to,
                                                                                 payload)))
        return True

    def deliver(self, t: float) -> list[Message]:
        """Remove and return the messages that have arrived by time t."""
        out: list[Message] = []
        while self._queue and self._queue[0][0] <= t + 1e-9:
            message = heapq.heappop(self._queue)[2]
            if message[1] not in self._silent:
                out.append(message)
                self._read[message[1]] += 1
        return out

    def take_reads(self) -> Counter[str]:
        """How many messages each receiver got since the last call (what eq. 5's battery spends)."""
        reads, self._read = self._read, Counter()
        return reads

    def pending(self) -> int:
        return len(self._queue)
