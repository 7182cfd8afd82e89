"""What built-ins and primitives may ask of the engine that runs them: the clock and the radio."""

from __future__ import annotations

from typing import Any, Protocol

from hfsm.runtime.agent import Agent, Frame, Region
from hfsm.runtime.team import Team


class Host(Protocol):
    tick: int
    team: Team

    @property
    def dt(self) -> float:
        """Seconds per tick."""

    @property
    def time(self) -> float:
        """Seconds at this tick."""

    def span(self, seconds: float) -> int:
        """Ticks of a span of seconds begun now (docs/REFERENCE.md#time-and-timers)."""

    def send(
        self, agent: Agent, where: Frame | Region, name: str, to: str, data: dict[str, Any], keep: str = "all"
    ) -> str:
        """Post a message from the behaviour running at `where`; a problem as text, or ''."""
