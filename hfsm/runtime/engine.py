"""What one agent does in one tick (docs/REFERENCE.md#time-and-timers, docs/REFERENCE.md#parallel-states,
docs/REFERENCE.md#watches), and the messages between agents.

Within a tick, for each agent, from the outermost machine inwards: at each level the machine's
timer, the state's timer, the earliest mapped message, the state's watches, a retry whose delay
ended; then below it: a called machine's level, each region of a parallel state in order (then
the join), or the running behaviour's own end.
"""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Message
from hfsm.runtime.agent import Agent, Event, Frame, Region, leaves
from hfsm.runtime.core import FatalError
from hfsm.runtime.holds import Holds
from hfsm.runtime.program import RMachine
from hfsm.runtime.scopes import radio_at
from hfsm.runtime.scopes import targets as scoped_targets
from hfsm.runtime.states import RState
from hfsm.world import NOTICE

__all__ = ["Engine", "FatalError"]


class Engine(Holds):
    def start(self, agent: Agent, top: RMachine, params: dict[str, Any]) -> None:
        agent.started = True
        self.emit(agent, [agent.top], "enter")
        root = agent.root = Frame(top, params, agent, None)
        ended = self._begin_machine(root)
        if ended is not None:
            self._end_agent(agent, ended)

    def step(self, frame: Frame) -> None:
        """An agent's turn in this tick, from its top machine's frame down."""
        k = self.tick
        while True:
            if frame.deadline == k:
                self._machine_timeout(frame)
                return
            state = frame.state
            if frame.state_deadline == k:
                self._state_timeout(frame)
                return
            if frame.agent.mailbox and state.msg_arcs and self._message_arc(frame, state):
                return
            if state.stepped and self._watched(frame, k):
                return
            below = frame.below
            cls = below.__class__
            if cls is Frame:
                frame = below
                continue
            if cls is list:
                self._step_regions(frame, below)
            elif below is not None and (below.deadline is None or below.deadline <= k):
                ended = below.advance(k)
                if ended is not None:
                    frame.below = None
                    if state.retry_on:
                        self._after_call(frame, ended)
                    else:  # _settle's work, without its call (a held state lets the end go: _held)
                        ended = self._run(frame, ended)
                        if ended is not None:
                            self._pass_up(frame, ended)
            return

    def _state_timeout(self, frame: Frame) -> None:
        """The state's timer fired: its `timeout` arc taken, or held."""
        if frame.state.autonomy and self._timer_held(frame):
            return
        self.emit(frame.agent, frame.path(), "timeout", timer="state")
        self._settle(frame, self._cancelled(frame, "timeout", Event("timeout")))

    def _message_arc(self, frame: Frame, state: RState) -> bool:
        """The earliest message the state maps takes its arc (or is held): whether one did. A state
        that holds an arc looks at no message."""
        if frame.held is not None:
            return False
        if state.autonomy and self._message_held(frame, state):
            return True
        message = frame.agent.take_message(state.msg_arcs, frame.radio.prefix)
        if message is None:
            return False
        event = Event(message.name, message=message)
        self._settle(frame, self._cancelled(frame, message.name, event))
        return True

    def _watched(self, frame: Frame, k: int) -> bool:
        """The state's watches, then the end of a retry's delay: whether either acted (neither, while
        the state holds an arc)."""
        if frame.held is not None:
            return False
        state = frame.state
        if state.watches:
            event = self._watch(frame, state)
            if event is not None:
                self._settle(frame, self._cancelled(frame, event.name, event))
                return True
        if frame.retry_at == k:
            frame.retry_at = None
            self._next_attempt(frame)
            self._after_call(frame, self._start_call(frame, state, frame))
            return True
        return False

    def _after_call(self, frame: Frame, event: Event | None) -> None:
        if frame.held is not None:
            return  # its state holds another arc: the callee's end is let go
        if event is not None and frame.state.retry_on:
            event = self._retry(frame, event)
        if event is not None:
            self._settle(frame, event)

    def _machine_timeout(self, frame: Frame) -> None:
        self.emit(frame.agent, frame.prefix(), "timeout", timer="machine")
        problem = self._cancel_below(frame, "timeout")
        if problem:
            self._settle(frame, Event("error", error=problem))
            return
        self._leave(frame, "timeout")
        self._pass_up(frame, self._finish(frame, "timeout"))

    # --- messages ------------------------------------------------------------------------------

    def send(self, agent: Agent, where: Frame | Region, name: str, to: str, data: dict[str, Any]) -> str:
        """Post a message, its name qualified by the scope it is sent under; a problem as text, or ''."""
        radio = radio_at(where)
        if not radio.top:
            chosen = scoped_targets(radio, agent.name, to)
            if isinstance(chosen, str):
                return chosen
            targets = chosen
            name = radio.prefix + name
        elif to == "others":
            targets = [a.name for a in self.agents if a is not agent]
        elif to == "all":
            targets = [a.name for a in self.agents]
        elif to in self.by_name:
            targets = [to]
        else:
            return f"send: no agent named '{to}' (agents: {', '.join(self.by_name)})"
        if self.trace is not None:
            self.emit(agent, where.path(), "send", message=name, to=to, data=data)
        for target in targets:
            self.world.post(Message(name, agent.name, target, dict(data), self.tick))
        return ""

    def deliver(self, messages: list[Message]) -> None:
        for message in messages:
            agent = self.by_name.get(message.to)
            if agent is None or agent.failed is not None:
                continue  # lost: nobody hears it
            if message.name == NOTICE:
                self.team.receive(message)
                continue
            agent.mailbox.append(message)
            if self.trace is not None:
                path = _first_leaf(agent)
                self.emit(
                    agent, path, "receive", message=message.name, sender=message.sender, data=message.data
                )


def _first_leaf(agent: Agent) -> list[str]:
    if agent.root is None:
        return [agent.top]
    return next(leaves(agent.root)).path()
