"""Transitions: what one agent does in one tick, and the zero-time chains that follow an event.

Within a tick, for each agent, from the outermost machine inwards: the machine's timer, then the
state's timer, then the earliest mapped message; last, the running behaviour's own end (SPEC 5).
"""

from __future__ import annotations

from typing import Any

from hfsm.expr import ExprValueError
from hfsm.primitive import Message
from hfsm.runtime.agent import Agent, AgentResult, Event, Frame
from hfsm.runtime.barrier import Team
from hfsm.runtime.builtins import STARTERS
from hfsm.runtime.primitives import PrimitiveActivity, RunContext
from hfsm.runtime.program import RMachine, RState, resolve_params, span_ticks, timer_ticks
from hfsm.spec import is_finite_number
from hfsm.trace import TraceSink
from hfsm.world import NOTICE, World

MAX_ENTRIES = 1000


class FatalError(Exception):
    """Ends the whole run at once (exit 1): an error at the top, too many entries in one tick."""

    def __init__(self, agent: str, message: str, traceback: str = "") -> None:
        super().__init__(message)
        self.agent = agent
        self.traceback = traceback


class Engine:
    def __init__(self, agents: list[Agent], world: World, dt: float, trace: TraceSink | None) -> None:
        self.agents = agents
        self.by_name = {a.name: a for a in agents}
        self.world = world
        self.dt = dt
        self.trace = trace
        self.tick = 0
        self._time = (0, 0.0)  # (tick, seconds) of the last time asked for
        self.running = len(agents)  # agents whose top machine has not ended
        self.spans: dict[float, int] = {}  # seconds -> ticks, for spans seen before
        self.team = Team(self)

    @property
    def time(self) -> float:
        """Seconds at this tick, k * dt rounded: traces print 0.15, not 0.15000000000000002."""
        tick, seconds = self._time
        if tick != self.tick:
            seconds = round(self.tick * self.dt, 9)
            self._time = (self.tick, seconds)
        return seconds

    def emit(self, agent: Agent, path: list[str], kind: str, **extra: Any) -> None:
        if self.trace is not None:
            self.trace.write({"t": self.time, "agent": agent.name, "path": path, "kind": kind, **extra})

    # --- one agent, one tick -------------------------------------------------------------------

    def start(self, agent: Agent, top: RMachine, params: dict[str, Any]) -> None:
        agent.started = True
        self.emit(agent, [agent.top], "enter")
        self._settle(agent, -1, self._start_machine(agent, top, params))

    def step(self, agent: Agent) -> None:
        k = self.tick
        stack = agent.stack
        for level, frame in enumerate(stack):
            if frame.deadline == k:
                self.emit(agent, agent.path(level)[:-1], "timeout", timer="machine")
                self._cancel_below(agent, level, "timeout")
                self._leave(agent, level, "timeout")
                self._settle(agent, level - 1, self._finish(agent, "timeout"))
                return
            if frame.state_deadline == k:
                self.emit(agent, agent.path(level), "timeout", timer="state")
                self._cancel_below(agent, level, "timeout")
                self._settle(agent, level, Event("timeout"))
                return
            if agent.mailbox and frame.state.msg_arcs:
                message = agent.take_message(frame.state.msg_arcs)
                if message is not None:
                    self._cancel_below(agent, level, message.name)
                    self._settle(agent, level, Event(message.name, message=message))
                    return
        activity = stack[-1].activity
        if activity is not None and (activity.deadline is None or activity.deadline <= k):
            event = activity.advance(k)
            if event is not None:
                stack[-1].activity = None
                self._settle(agent, len(stack) - 1, event)

    # --- events and chains ---------------------------------------------------------------------

    def _settle(self, agent: Agent, level: int, event: Event | None) -> None:
        """Hand `event` to the state at `level`, and each machine's ending to its caller, up to the top."""
        while event is not None:
            if level < 0:
                self._end_agent(agent, event)
                return
            event = self._run(agent, level, event)
            level -= 1

    def _run(self, agent: Agent, level: int, event: Event) -> Event | None:
        """Take arcs from the state at `level` until it waits; an Event back means its machine ended."""
        while True:
            target = self._arc(agent, level, event)
            if target is None:
                return self._abort(agent, event)
            if isinstance(target, str):
                return self._finish(agent, target)
            entered = self._enter(agent, level, target)
            if entered is None:
                return None
            event = entered

    def _arc(self, agent: Agent, level: int, event: Event) -> RState | str | None:
        frame = agent.stack[level]
        state = frame.state
        name = event.name
        target: RState | str | None
        if event.goto is not None:
            target = event.goto
        elif name == "error":
            if not event.origin:
                event.origin = "/".join(agent.path(level))
                self.emit(agent, agent.path(level), "error", message=event.error)
            target = state.error_target
        elif event.message is not None:
            target = state.msg_arcs[name]
        else:
            found = state.arcs.get(name)
            if found is None:
                spec_name = state.do
                error = f"'{spec_name}' ended with '{name}', which is not one of its outcomes"
                return self._arc(agent, level, Event("error", error=error))
            target = found
            if state.save and event.outputs:
                for var, output in state.save:
                    if output in event.outputs:
                        frame.vars[var] = event.outputs[output]
        if self.trace is not None:
            shown = target.name if target.__class__ is RState else target
            self.emit(agent, agent.path(level), "event", event=name, target=shown)
        self._leave(agent, level, name)
        return target

    def _leave(self, agent: Agent, level: int, event: str) -> None:
        frame = agent.stack[level]
        if self.trace is not None:
            self.emit(agent, agent.path(level), "exit", event=event)
        state = frame.state
        if not state.is_choice:
            stats = agent.stats.get(state.do) or agent.new_stats(state.do)
            stats.calls += 1
            stats.ticks += self.tick - frame.entered
            stats.events[event] = stats.events.get(event, 0) + 1

    def _enter(self, agent: Agent, level: int, state: RState) -> Event | None:
        frame = agent.stack[level]
        frame.state = state
        frame.entered = self.tick
        frame.state_deadline = None
        if self.trace is not None:
            self.emit(agent, agent.path(level), "enter", **({"do": state.do} if state.do else {}))
        agent.entries += 1
        if agent.entries > MAX_ENTRIES:
            path = "/".join(agent.path(level))
            raise FatalError(agent.name, f"{path}: more than {MAX_ENTRIES} state entries in one tick")
        if state.is_choice:
            return self._choose(frame, state)
        if state.timer is not None:
            ticks = self._ticks(state.timer, frame)
            if ticks.__class__ is Event:
                return ticks
            frame.state_deadline = self.tick + ticks  # type: ignore[operator]
        if agent.mailbox and state.msg_arcs:
            message = agent.take_message(state.msg_arcs)
            if message is not None:
                return Event(message.name, message=message)
        params = state.params if state.params is not None else self._params(state, frame)
        if params.__class__ is Event:
            return params
        return self._call(agent, state, frame, params)  # type: ignore[arg-type]

    def _choose(self, frame: Frame, state: RState) -> Event:
        for condition, text, target in state.branches:
            if condition is None:
                return Event("else", goto=target)
            try:
                if condition(frame.scope):
                    return Event(text, goto=target)
            except ExprValueError as exc:
                return Event("error", error=f"in '{text}': {exc}")
        raise AssertionError("a checked choice ends with else")

    def _ticks(self, timer: Any, frame: Frame) -> int | Event:
        if timer.__class__ is int:
            return timer
        try:
            seconds = timer(frame.scope)
        except ExprValueError as exc:
            return Event("error", error=f"timer: {exc}")
        if not is_finite_number(seconds) or seconds <= 0:
            return Event("error", error=f"timer must be a positive number of seconds, not {seconds!r}")
        return timer_ticks(seconds, self.dt)

    def _params(self, state: RState, frame: Frame) -> dict[str, Any] | Event:
        if state.params is not None:
            return state.params
        try:
            given = {k: v.fn(frame.scope) for k, v in state.with_.items()}
        except ExprValueError as exc:
            return Event("error", error=str(exc))
        params = resolve_params(state.spec, given)  # type: ignore[arg-type]
        return Event("error", error=params) if isinstance(params, str) else params

    def _call(self, agent: Agent, state: RState, frame: Frame, params: dict[str, Any]) -> Event | None:
        kind = state.kind
        if kind == "machine":
            agent.stack.append(Frame(state.callee, params, agent, self))  # type: ignore[arg-type]
            return self._run_new_machine(agent)
        if kind == "primitive":
            ctx = RunContext(self, agent, state.do)
            origin = "/".join(agent.path(len(agent.stack) - 1))
            activity: Any = PrimitiveActivity(state.callee, ctx, params, origin)  # type: ignore[arg-type]
        else:
            activity = STARTERS[kind](self, agent, frame, params)
        event = activity if activity.__class__ is Event else activity.advance(self.tick)
        if event is None:
            frame.activity = activity
        return event

    def _start_machine(self, agent: Agent, machine: RMachine, params: dict[str, Any]) -> Event | None:
        agent.stack.append(Frame(machine, params, agent, self))
        return self._run_new_machine(agent)

    def _run_new_machine(self, agent: Agent) -> Event | None:
        level = len(agent.stack) - 1
        frame = agent.stack[level]
        machine = frame.machine
        if machine.timer is not None:
            ticks = self._ticks(machine.timer, frame)
            if ticks.__class__ is Event:
                agent.stack.pop()
                ticks.origin = "/".join(agent.path(level - 1)) if level else agent.top
                return ticks
            frame.deadline = self.tick + ticks  # type: ignore[operator]
        event = self._enter(agent, level, machine.initial)  # type: ignore[arg-type]
        return None if event is None else self._run(agent, level, event)

    def _finish(self, agent: Agent, outcome: str) -> Event:
        """The innermost machine ends in `outcome`: evaluate its outputs and pop its frame."""
        frame = agent.stack.pop()
        machine = frame.machine
        if not machine.outputs:
            ending = machine.endings.get(outcome)
            if ending is None:
                ending = machine.endings[outcome] = Event(outcome, {})
            return ending
        outputs = {}
        try:
            for name, value in machine.outputs.items():
                outputs[name] = value.fn(frame.scope)
        except ExprValueError as exc:
            return Event("error", error=f"outputs of '{machine.name}': {exc}")
        return Event(outcome, outputs)

    def _abort(self, agent: Agent, event: Event) -> Event:
        """An unmapped error ends the innermost machine; the error passes to its caller."""
        agent.stack.pop()
        return event

    def _cancel_below(self, agent: Agent, level: int, reason: str) -> None:
        """Cancel whatever runs below the state at `level` (all of it, for level -1)."""
        stack = agent.stack
        while len(stack) > level + 1:
            inner = stack[-1]
            if inner.activity is not None:
                inner.activity.cancel()
                inner.activity = None
            self._leave(agent, len(stack) - 1, reason)
            stack.pop()
        if level >= 0 and stack[level].activity is not None:
            stack[level].activity.cancel()  # type: ignore[union-attr]
            stack[level].activity = None

    def span(self, seconds: float) -> int:
        ticks = self.spans.get(seconds)
        if ticks is None:
            ticks = self.spans[seconds] = span_ticks(seconds, self.dt)
        return ticks

    def stop(self, agent: Agent, reason: str = "stopped") -> None:
        """End an agent that has not ended: cancel what runs, close its trace."""
        if not agent.started:
            return
        self._cancel_below(agent, -1, reason)
        self.emit(agent, [agent.top], "exit", outcome=None)

    def _end_agent(self, agent: Agent, event: Event) -> None:
        self.running -= 1
        if event.name == "error" and event.goto is None:
            agent.result = AgentResult(None, {}, self.time)
            self.emit(agent, [agent.top], "exit", outcome=None)
            origin = event.origin or agent.top
            raise FatalError(agent.name, f"{origin}: {event.error}", event.traceback)
        agent.result = AgentResult(event.name, event.outputs or {}, self.time)
        self.emit(agent, [agent.top], "exit", outcome=event.name)

    # --- messages ------------------------------------------------------------------------------

    def send(self, agent: Agent, name: str, to: str, data: dict[str, Any]) -> str:
        """Post a message; return a problem as text, or ''."""
        if to == "others":
            targets = [a.name for a in self.agents if a is not agent]
        elif to == "all":
            targets = [a.name for a in self.agents]
        elif to in self.by_name:
            targets = [to]
        else:
            return f"send: no agent named '{to}' (agents: {', '.join(self.by_name)})"
        self.emit(agent, agent.path(len(agent.stack) - 1), "send", message=name, to=to, data=data)
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
            path = agent.path(len(agent.stack) - 1) if agent.stack else [agent.top]
            self.emit(agent, path, "receive", message=message.name, sender=message.sender, data=message.data)

