"""The run's clock: the tick, its length, its time in seconds, spans as ticks; and whether the next tick
is due though no timer says so (docs/REFERENCE.md#time-and-timers). Every part of the engine that
reads the time is given this clock."""

from __future__ import annotations

from hfsm.runtime.program import span_ticks


class RunClock:
    def __init__(self, dt: float) -> None:
        self.dt = dt
        self.tick = 0
        self._time = (0, 0.0)  # (tick, seconds) of the last time asked for
        self.spans: dict[float, int] = {}  # seconds -> ticks, for spans seen before
        self.wake = False  # vars changed after a state's watches were tried: its next tick is due

    @property
    def time(self) -> float:
        """Seconds at this tick, k * dt rounded: traces print 0.15, not 0.15000000000000002."""
        tick, seconds = self._time
        if tick != self.tick:
            seconds = round(self.tick * self.dt, 9)
            self._time = (self.tick, seconds)
        return seconds

    def span(self, seconds: float) -> int:
        ticks = self.spans.get(seconds)
        if ticks is None:
            ticks = self.spans[seconds] = span_ticks(seconds, self.dt)
        return ticks
