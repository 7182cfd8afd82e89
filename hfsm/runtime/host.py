"""What built-ins and primitives may ask of the engine that runs them: the clock and the radio."""

from __future__ import annotations

from typing import Any, Protocol

from hfsm.runtime.agent import Agent, Frame, Region
from hfsm.runtime.barrier import Team


class Host(Protocol):
    dt: float
    tick: int
    team: Team

    @property
    def time(self) -> float:
        """Seconds at this tick."""

    def span(self, seconds: float) -> int:
        """Ticks of a span of seconds begun now (docs/REFERENCE.md#time-and-timers)."""

    def send(self, agent: Agent, where: Frame | Region, name: str, to: str, data: dict[str, Any]) -> str:
        """Post a message from the behaviour running at `where`; a problem as text, or ''."""
