"""The engine: one object composed of parts with one job each, each given the parts it uses.

The clock (clock.py) and the ledger of records and statistics (ledger.py) are read by all; the
tick loop (loop.py) steps each agent; arcs.py takes events and enters states; calls.py starts
behaviours, machines and retries; parallel.py runs regions; timers.py makes spans ticks and fires
timers; messaging.py is the radio; cancel.py cancels what runs below a state; holds.py keeps arcs
for the operator. The engine's state is plain attributes of these parts: it pickles (hfsm-verify).
"""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Message
from hfsm.runtime.agent import Agent, Frame, Region
from hfsm.runtime.arcs import Arcs
from hfsm.runtime.calls import Calls
from hfsm.runtime.cancel import Cancelling
from hfsm.runtime.clock import RunClock
from hfsm.runtime.core import FatalError
from hfsm.runtime.enginestate import EngineState
from hfsm.runtime.holds import Holds
from hfsm.runtime.ledger import Ledger
from hfsm.runtime.loop import Loop
from hfsm.runtime.messaging import Messaging
from hfsm.runtime.parallel import Regions
from hfsm.runtime.program import RMachine
from hfsm.runtime.records import records_for
from hfsm.runtime.scopes import Radio
from hfsm.runtime.states import RState
from hfsm.runtime.team import Team
from hfsm.runtime.timers import Timers
from hfsm.trace import TraceSink
from hfsm.world import World

__all__ = ["Engine", "EngineState", "FatalError", "restore_engine"]


class Engine:
    def __init__(
        self,
        agents: list[Agent],
        world: World,
        dt: float,
        trace: TraceSink | None,
        clock: RunClock | None = None,
        team: Team | None = None,
    ) -> None:
        """`clock` and `team`: an engine's own, when it is made again from a snapshot."""
        self.agents = agents
        self.by_name = {a.name: a for a in agents}
        self.world: World = world
        self.trace = trace
        clock = self.clock = clock or RunClock(dt)
        for agent in agents:
            agent.clock = clock
            agent.radio = Radio("", tuple(a.name for a in agents if a is not agent), top=True)
        self.team = team or Team(agents, world, clock)  # barriers (docs/REFERENCE.md#barriers)
        self.records = records_for(trace, clock)
        self.breaks: Any = None  # the breakpoints' sink (runtime.breaks.Breaks), when there are any
        ledger = self.ledger = Ledger(clock, self.records)
        cancelling = self.cancelling = Cancelling(ledger)
        timers = Timers(clock, ledger, cancelling)
        calls = Calls(clock, ledger, timers, self)
        holds = self.holds = Holds(agents, ledger, cancelling)
        regions = Regions(clock, ledger, calls, cancelling)
        arcs = Arcs(clock, ledger, calls, timers, self.team.order)
        mailbox = self.mailbox = Messaging(agents, world, self.team, clock, ledger, cancelling)
        loop = self.loop = Loop(clock, ledger, calls, arcs, regions, timers, mailbox, cancelling, len(agents))
        # The calls between parts go both ways: each is given those built after it.
        timers.arcs, timers.calls, timers.holds = arcs, calls, holds
        calls.arcs = arcs
        holds.arcs, holds.regions = arcs, regions
        regions.arcs, regions.loop = arcs, loop
        arcs.holds, arcs.regions, arcs.loop = holds, regions, loop
        mailbox.arcs, mailbox.holds = arcs, holds

    # --- its state between ticks -----------------------------------------------------------------

    def snapshot(self) -> EngineState:
        """What changes between ticks (a view, not a copy); an engine writing a trace has none."""
        if self.records is not None or self.breaks is not None:
            raise ValueError("an engine that writes a trace or has breakpoints is not snapshotted")
        return EngineState(
            self.agents, self.world, self.clock, self.team, self.loop.running, self.holds.level,
            self.holds.approved, self.mailbox.sent, [a.radio for a in self.agents],
        )  # fmt: skip

    def __reduce__(self) -> tuple[Any, tuple[EngineState]]:
        return restore_engine, (self.snapshot(),)

    # --- the clock ---------------------------------------------------------------------------------

    @property
    def tick(self) -> int:
        return self.clock.tick

    @tick.setter
    def tick(self, tick: int) -> None:
        self.clock.tick = tick

    @property
    def dt(self) -> float:
        return self.clock.dt

    @property
    def time(self) -> float:
        """Seconds at this tick."""
        return self.clock.time

    def span(self, seconds: float) -> int:
        """Ticks of a span of seconds begun now (docs/REFERENCE.md#time-and-timers)."""
        return self.clock.span(seconds)

    @property
    def spans(self) -> dict[float, int]:
        return self.clock.spans

    @property
    def wake(self) -> bool:
        """Whether the next tick is due though no timer says so (vars changed after watches were tried)."""
        return self.clock.wake

    @wake.setter
    def wake(self, wake: bool) -> None:
        self.clock.wake = wake

    # --- agents --------------------------------------------------------------------------------------

    @property
    def running(self) -> int:
        """Agents whose top machine has not ended."""
        return self.loop.running

    @running.setter
    def running(self, running: int) -> None:
        self.loop.running = running

    def start(self, agent: Agent, top: RMachine, params: dict[str, Any]) -> None:
        self.loop.start(agent, top, params)

    def step(self, frame: Frame) -> None:
        """An agent's turn in this tick, from its top machine's frame down."""
        self.loop.step(frame)

    def stop(self, agent: Agent, reason: str = "stopped") -> None:
        """End an agent that has not ended: cancel what runs, close its trace."""
        self.cancelling.stop(agent, reason)

    def emit(self, agent: Agent, path: list[str], kind: str, **extra: Any) -> None:
        self.ledger.emit(agent, path, kind, **extra)

    # --- the radio -----------------------------------------------------------------------------------

    def send(
        self, agent: Agent, where: Frame | Region, name: str, to: str, data: dict[str, Any], keep: str = "all"
    ) -> str:
        """Post a message from the behaviour running at `where`; a problem as text, or ''."""
        return self.mailbox.send(agent, where, name, to, data, keep)

    def deliver(self, messages: list[Message]) -> None:
        self.mailbox.deliver(messages)

    # --- the operator --------------------------------------------------------------------------------

    @property
    def level(self) -> int:
        """The run's autonomy level."""
        return self.holds.level

    @level.setter
    def level(self, level: int) -> None:
        self.holds.level = level

    def answered(self, agent: Agent, do: str, event: str | None) -> tuple[Frame | None, str]:
        return self.holds.answered(agent, do, event)

    def accept(self, frame: Frame) -> None:
        self.holds.accept(frame)

    def force(self, frame: Frame, event: str) -> None:
        self.holds.force(frame, event)

    def set_level(self, level: int) -> None:
        self.holds.set_level(level)

    @staticmethod
    def events(state: RState) -> list[str]:
        """The events whose arcs the operator may force in `state`."""
        return Holds.events(state)


def restore_engine(state: EngineState) -> Engine:
    """An engine in `state`, its parts made anew (the agents, their trees and the world are `state`'s)."""
    engine = Engine(state.agents, state.world, state.clock.dt, None, state.clock, state.team)
    engine.loop.running = state.running
    engine.holds.level, engine.holds.approved = state.level, state.approved
    engine.mailbox.sent = state.sent
    for agent, radio in zip(state.agents, state.radios, strict=True):
        agent.radio = radio
    return engine
