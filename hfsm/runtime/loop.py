"""What one agent does in one tick (docs/REFERENCE.md#time-and-timers, docs/REFERENCE.md#parallel-states,
docs/REFERENCE.md#watches), and how an agent starts and ends.

Within a tick, for each agent, from the outermost machine inwards: at each level the machine's
timer, the state's timer, the earliest mapped message, the state's watches, a retry whose delay
ended; then below it: a called machine's level, each region of a parallel state in order (then
the join), or the running behaviour's own end.
"""

from __future__ import annotations

from typing import Any

from hfsm.runtime.agent import Agent, AgentResult, Event, Frame
from hfsm.runtime.arcs import Arcs
from hfsm.runtime.calls import Calls
from hfsm.runtime.cancel import Cancelling
from hfsm.runtime.clock import RunClock
from hfsm.runtime.core import FatalError
from hfsm.runtime.ledger import Ledger
from hfsm.runtime.messaging import Messaging
from hfsm.runtime.parallel import Regions
from hfsm.runtime.program import RMachine
from hfsm.runtime.timers import Timers


class Loop:
    def __init__(
        self,
        clock: RunClock,
        ledger: Ledger,
        calls: Calls,
        arcs: Arcs,
        regions: Regions,
        timers: Timers,
        mailbox: Messaging,
        cancelling: Cancelling,
        running: int,
    ) -> None:
        self.clock = clock
        self.ledger = ledger
        self.calls = calls
        self.arcs = arcs
        self.regions = regions
        self.timers = timers
        self.mailbox = mailbox
        self.cancelling = cancelling
        self.running = running  # agents whose top machine has not ended

    def start(self, agent: Agent, top: RMachine, params: dict[str, Any]) -> None:
        agent.started = True
        self.ledger.emit(agent, [agent.top], "enter")
        root = agent.root = Frame(top, params, agent, None)
        ended = self.calls.begin_machine(root)
        if ended is not None:
            self.end_agent(agent, ended)

    def step(self, frame: Frame) -> None:
        """An agent's turn in this tick, from its top machine's frame down."""
        k = self.clock.tick
        while True:
            if frame.deadline == k:
                self.timers.machine_timeout(frame)
                return
            state = frame.state
            if frame.state_deadline == k:
                self.timers.state_timeout(frame)
                return
            if frame.agent.mailbox and state.msg_arcs and self.mailbox.message_arc(frame, state):
                return
            if state.stepped and self._watched(frame, k):
                return
            below = frame.below
            cls = below.__class__
            if cls is Frame:
                frame = below
                continue
            if cls is list:
                self.regions.step_regions(frame, below)
            elif below is not None and (below.deadline is None or below.deadline <= k):
                ended = below.advance(k)
                if ended is not None:
                    frame.below = None
                    if state.retry_on:
                        self._after_call(frame, ended)
                    else:  # settle's work, without its call (a held state lets the end go: Holds.held)
                        ended = self.arcs.run(frame, ended)
                        if ended is not None:
                            self.arcs.pass_up(frame, ended)
            return

    def _watched(self, frame: Frame, k: int) -> bool:
        """The state's watches, then the end of a retry's delay: whether either acted (neither, while
        the state holds an arc)."""
        if frame.held is not None:
            return False
        state = frame.state
        if state.watches:
            event = self.arcs.watch(frame, state)
            if event is not None:
                self.arcs.settle(frame, self.cancelling.cancelled(frame, event.name, event))
                return True
        if frame.retry_at == k:
            frame.retry_at = None
            self.calls.next_attempt(frame)
            self._after_call(frame, self.calls.start_call(frame, state, frame))
            return True
        return False

    def _after_call(self, frame: Frame, event: Event | None) -> None:
        if frame.held is not None:
            return  # its state holds another arc: the callee's end is let go
        if event is not None and frame.state.retry_on:
            event = self.calls.retry(frame, event)
        if event is not None:
            self.arcs.settle(frame, event)

    def end_agent(self, agent: Agent, event: Event) -> None:
        self.running -= 1
        agent.root = None
        if event.name == "error" and event.goto is None:
            agent.result = AgentResult(None, {}, self.clock.time)
            self.ledger.emit(agent, [agent.top], "exit", outcome=None)
            origin = event.origin or agent.top
            raise FatalError(agent.name, f"{origin}: {event.error}", event.traceback, origin, event.where)
        agent.result = AgentResult(event.name, event.outputs or {}, self.clock.time)
        self.ledger.emit(agent, [agent.top], "exit", outcome=event.name)
