"""What the run writes down: trace records, and each behaviour's statistics as its states are left."""

from __future__ import annotations

from typing import Any

from hfsm.runtime.agent import Agent, Frame, Region
from hfsm.runtime.clock import RunClock
from hfsm.runtime.records import Records


class Ledger:
    def __init__(self, clock: RunClock, records: Records | None) -> None:
        self.clock = clock
        self.records = records  # None: no trace

    def emit(self, agent: Agent, path: list[str], kind: str, **extra: Any) -> None:
        if self.records is not None:
            self.records.write(agent, path, kind, **extra)

    def leave(self, frame: Frame, event: str) -> None:
        """The trace's `exit` of a frame's current state, and the statistics of its behaviour."""
        if self.records is not None:
            self.records.write(frame.agent, frame.path(), "exit", event=event)
        if frame.state.do:
            self.count(frame.agent, frame.state.do, frame.entered, event)

    def region_left(self, region: Region, event: str) -> None:
        if self.records is not None:
            self.records.write(region.owner.agent, region.path(), "exit", event=event)
        self.count(region.owner.agent, region.spec.do, region.owner.entered, event)

    def count(self, agent: Agent, behaviour: str, entered: int, event: str) -> None:
        stats = agent.stats.get(behaviour) or agent.new_stats(behaviour)
        stats.calls += 1
        stats.ticks += self.clock.tick - entered
        stats.events[event] = stats.events.get(event, 0) + 1
