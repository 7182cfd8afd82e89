"""What expressions read while a state runs: the time since entry, the attempt, the world's inputs."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Protocol

from hfsm.expr import ExprValueError
from hfsm.world import InputSpec, World


class Clock(Protocol):
    tick: int
    dt: float


class Inputs:
    """One agent's inputs: each read from the world at most once a tick, and only when asked."""

    __slots__ = ("_agent", "_cache", "_declared", "_tick", "_world")

    def __init__(self, world: World, agent: str) -> None:
        self._world = world
        self._agent = agent
        self._declared: Mapping[str, InputSpec] | None = None
        self._cache: dict[str, Any] = {}
        self._tick = -1

    def read(self, name: str, tick: int) -> Any:
        if tick != self._tick:
            self._cache.clear()
            self._tick = tick
        if name in self._cache:
            return self._cache[name]
        if self._declared is None:
            self._declared = self._world.inputs()
        if name not in self._declared:
            raise ExprValueError(f"world '{self._world.name}' declares no input 'in.{name}'")
        try:
            value = self._world.read_input(self._agent, name, tick)
        except Exception as exc:  # a world's failure to sense is the machine's `error`
            raise ExprValueError(f"in.{name}: {type(exc).__name__}: {exc}") from None
        self._cache[name] = value
        return value

    def peek(self, name: str, tick: int) -> Any:
        """What the machines read of `name` in `tick`, never asking the world: an observer (a condition
        breakpoint) must not change the run, and a world's read can draw from its random streams."""
        if tick != self._tick or name not in self._cache:
            raise NotRead(f"in.{name} was not read by the agent's machines in this tick")
        return self._cache[name]


class NotRead(LookupError):
    """An input an observer asked for that the machines did not read in the tick."""


def seconds(ticks: int, dt: float) -> float:
    """A count of ticks as seconds, rounded to 9 places: 6 * 0.05 is 0.3 (docs/REFERENCE.md#watches)."""
    return round(ticks * dt, 9)


class FrameLive:
    """The live names of one running machine frame: `state.*` of its current state, `machine.time`."""

    __slots__ = ("clock", "frame", "inputs")

    def __init__(self, frame: Any, clock: Clock, inputs: Inputs) -> None:
        self.frame = frame
        self.clock = clock
        self.inputs = inputs

    def state_time(self) -> float:
        entered: int = getattr(self.frame, "entered", self.clock.tick)  # unset before its first state
        return seconds(self.clock.tick - entered, self.clock.dt)

    def state_attempt(self) -> int:
        attempt: int = getattr(self.frame, "attempt", 1)
        return attempt

    def machine_time(self) -> float:
        return seconds(self.clock.tick - self.frame.started, self.clock.dt)

    def input(self, name: str) -> Any:
        return self.inputs.read(name, self.clock.tick)

    def scope_name(self) -> str:
        frame = self.frame
        return str((frame.inner if frame.in_with else frame.radio).name)

    def scope_agents(self) -> list[str]:
        frame = self.frame
        return list((frame.inner if frame.in_with else frame.radio).agents)
