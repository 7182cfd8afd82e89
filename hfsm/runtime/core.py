"""The engine's ground floor: the clock, the trace, statistics, and how an agent ends.

The engine is built in layers, each a module with one job, each class extending the one below:
core (this) < cancel < calls < arcs < parallel < engine (the tick). A lower layer that needs
what a higher one does names it here, as a method the higher layer defines.
"""

from __future__ import annotations

from typing import Any

from hfsm.autonomy import FULL
from hfsm.runtime.agent import Agent, AgentResult, Event, Frame, Region
from hfsm.runtime.barrier import Team
from hfsm.runtime.program import span_ticks
from hfsm.runtime.records import records_for
from hfsm.runtime.scopes import Radio
from hfsm.runtime.states import RState
from hfsm.trace import TraceSink
from hfsm.world import World

MAX_ENTRIES = 1000


class FatalError(Exception):
    """Ends the whole run at once (exit 1): an error at the top, too many entries in one tick."""

    def __init__(
        self,
        agent: str,
        message: str,
        traceback: str = "",
        origin: str = "",
        where: tuple[str | int, ...] = (),
    ) -> None:
        super().__init__(message)
        self.agent = agent
        self.traceback = traceback
        self.origin = origin  # the path of the state (or region) where it happened, when known
        self.where = where  # the path of the expression that failed, in that state's machine file


class Core:
    def __init__(self, agents: list[Agent], world: World, dt: float, trace: TraceSink | None) -> None:
        self.agents = agents
        for agent in agents:
            agent.clock = self
        self.by_name = {a.name: a for a in agents}
        for agent in agents:
            agent.radio = Radio("", tuple(a.name for a in agents if a is not agent), top=True)
        self.world: World = world
        self.dt = dt
        self.trace = trace
        self.records = records_for(trace, self)
        self.tick = 0
        self._time = (0, 0.0)  # (tick, seconds) of the last time asked for
        self.running = len(agents)  # agents whose top machine has not ended
        self.spans: dict[float, int] = {}  # seconds -> ticks, for spans seen before
        self.team = Team(self)  # barriers (docs/REFERENCE.md#barriers)
        self.wake = False  # vars changed after a state's watches were tried: its next tick is due
        self.level = FULL  # the run's autonomy level
        self.approved: Event | None = None  # the event the operator answered: taken, not held again
        self.breaks: Any = None  # the breakpoints' sink (runtime.breaks.Breaks), when there are any

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

    def emit(self, agent: Agent, path: list[str], kind: str, **extra: Any) -> None:
        if self.records is not None:
            self.records.write(agent, path, kind, **extra)

    def _leave(self, frame: Frame, event: str) -> None:
        """The trace's `exit` of a frame's current state, and the statistics of its behaviour."""
        if self.trace is not None:
            self.emit(frame.agent, frame.path(), "exit", event=event)
        if frame.state.do:
            self._count(frame.agent, frame.state.do, frame.entered, event)

    def _region_left(self, region: Region, event: str) -> None:
        if self.trace is not None:
            self.emit(region.owner.agent, region.path(), "exit", event=event)
        self._count(region.owner.agent, region.spec.do, region.owner.entered, event)

    @staticmethod
    def _save(frame: Frame, save: tuple[tuple[str, str], ...], outputs: dict[str, Any]) -> None:
        """A state's `save`: the callee's outputs it names, into the machine's vars."""
        for var, output in save:
            if output in outputs:
                frame.vars[var] = outputs[output]
                frame.vars_shown = False

    def _count(self, agent: Agent, behaviour: str, entered: int, event: str) -> None:
        stats = agent.stats.get(behaviour) or agent.new_stats(behaviour)
        stats.calls += 1
        stats.ticks += self.tick - entered
        stats.events[event] = stats.events.get(event, 0) + 1

    def _end_agent(self, agent: Agent, event: Event) -> None:
        self.running -= 1
        agent.root = None
        if event.name == "error" and event.goto is None:
            agent.result = AgentResult(None, {}, self.time)
            self.emit(agent, [agent.top], "exit", outcome=None)
            origin = event.origin or agent.top
            raise FatalError(agent.name, f"{origin}: {event.error}", event.traceback, origin, event.where)
        agent.result = AgentResult(event.name, event.outputs or {}, self.time)
        self.emit(agent, [agent.top], "exit", outcome=event.name)

    # --- defined by the layers above -----------------------------------------------------------

    def _run(self, frame: Frame, event: Event) -> Event | None:
        raise NotImplementedError

    def _enter(self, frame: Frame, state: RState) -> Event | None:
        raise NotImplementedError

    def _held(self, frame: Frame, state: RState, event: Event) -> bool:
        raise NotImplementedError

    def _message_held(self, frame: Frame, state: RState) -> bool:
        raise NotImplementedError

    def _start_regions(self, frame: Frame) -> Event | None:
        raise NotImplementedError

    def _region_ended(self, region: Region, event: Event) -> None:
        raise NotImplementedError

    def send(self, agent: Agent, where: Frame | Region, name: str, to: str, data: dict[str, Any]) -> str:
        raise NotImplementedError
