"""Calling a behaviour: a state's or a region's `with`, the callee started, a machine's end, retries."""

from __future__ import annotations

from typing import Any

from hfsm.expr import ExprValueError
from hfsm.runtime.agent import CALLEE, Event, Frame, Region
from hfsm.runtime.clock import RunClock
from hfsm.runtime.host import Host
from hfsm.runtime.ledger import Ledger
from hfsm.runtime.parts import ArcsPart
from hfsm.runtime.primitives import PrimitiveActivity, RunContext
from hfsm.runtime.program import RMachine, resolve_params
from hfsm.runtime.states import Callee
from hfsm.runtime.timers import Timers, Where


def save(frame: Frame, names: tuple[tuple[str, str], ...], outputs: dict[str, Any]) -> None:
    """A state's `save`: the callee's outputs it names, into the machine's vars."""
    saved = []
    for var, output in names:
        if output in outputs:
            frame.vars[var] = outputs[output]
            saved.append(var)
    if saved:
        frame.changed(saved)


class Calls:
    arcs: ArcsPart

    def __init__(self, clock: RunClock, ledger: Ledger, timers: Timers, host: Host) -> None:
        self.clock = clock
        self.ledger = ledger
        self.timers = timers
        self.host = host  # what built-ins and primitives may ask of the engine

    @staticmethod
    def params(callee: Callee, frame: Frame) -> dict[str, Any] | Event:
        frame.in_with = True  # `scope.*` in a `with` reads the state's own scope (docs/REFERENCE.md#scopes)
        given = {}
        key = ""
        try:
            for key, value in callee.with_.items():
                given[key] = value.fn(frame.scope)
        except ExprValueError as exc:
            return Event("error", error=str(exc), where=(*callee.at, "with", key, *exc.where))
        finally:
            frame.in_with = False
        params = resolve_params(callee.spec, given)  # type: ignore[arg-type]
        return Event("error", error=params) if isinstance(params, str) else params

    def start_call(self, frame: Frame, callee: Callee, where: Frame | Region) -> Event | None:
        """Start `callee` below `where` (a call state's frame, or a region of `frame`'s state).

        `with` reads `frame`. Returns what it ended with at once, or None while it runs.
        """
        if callee.wait_ticks:  # a constant span: the activity made at once, without the starter's call
            where.below = callee.after(self.clock.tick + callee.wait_ticks)
            return None
        params = callee.params if callee.params is not None else self.params(callee, frame)
        if params.__class__ is Event:
            return params
        kind = callee.kind
        agent = frame.agent
        if kind == "machine":
            machine: RMachine = callee.callee  # type: ignore[assignment]
            child = where.below = Frame(machine, params, agent, where)  # type: ignore[arg-type]
            if machine.timer is None:  # begin_machine's work, without its call
                ended = self.arcs.enter(child, machine.initial)  # type: ignore[arg-type]
                if ended is not None:
                    ended = self.arcs.run(child, ended)
            else:
                ended = self.begin_machine(child)
            if ended is not None:
                where.below = None
            return ended
        if kind == "primitive":
            starts = getattr(callee.callee, "start_activity", None)  # a stand-in of hfsm-verify
            if starts is not None:
                activity: Any = starts(self.host, agent, params, where)
            else:
                ctx = RunContext(self.host, agent, callee.do, where)
                activity = PrimitiveActivity(callee.callee, ctx, params, where)  # type: ignore[arg-type]
        else:
            activity = callee.start(self.host, agent, frame, params, where)
            if activity.__class__ is Event:
                return activity
        event: Event | None = activity.advance(self.clock.tick)
        if event is None:
            where.below = activity
        return event

    def begin_machine(self, frame: Frame) -> Event | None:
        """A called machine starts: its timer, its initial state; its ending if it ends at once."""
        machine: RMachine = frame.machine
        if machine.timer is not None:
            ticks = self.timers.ticks(machine.timer, frame, (CALLEE, "timer"))
            if ticks.__class__ is Event:
                ticks.origin = "/".join(frame.prefix())
                return ticks
            frame.deadline = self.clock.tick + ticks  # type: ignore[operator]
        event = self.arcs.enter(frame, machine.initial)  # type: ignore[arg-type]
        return None if event is None else self.arcs.run(frame, event)

    @staticmethod
    def finish(frame: Frame, outcome: str) -> Event:
        """`frame`'s machine ends in `outcome`: its outputs evaluated."""
        machine = frame.machine
        if not machine.outputs:
            ending = machine.endings.get(outcome)
            if ending is None:
                ending = machine.endings[outcome] = Event(outcome, {})
            return ending
        outputs = {}
        for name, value in machine.outputs.items():
            try:
                outputs[name] = value.fn(frame.scope)
            except ExprValueError as exc:
                where = (CALLEE, "outputs", name, *exc.where)
                return Event("error", error=f"outputs of '{machine.name}': {exc}", where=where)
        return Event(outcome, outputs)

    def retry(self, frame: Frame, event: Event) -> Event | None:
        """The callee of `frame`'s state ended with `event`: call it again (docs/REFERENCE.md#retries), or
        hand it on."""
        state = frame.state
        while event.name in state.retry_on:
            times = self._count_of(state.retry_times, frame, "times", (*state.at, "retry", "times"))
            if times.__class__ is Event:
                return times
            if frame.attempt > times:  # type: ignore[operator]
                return event
            self._ended_once(frame, event)
            if self.ledger.records is not None:
                self.ledger.emit(
                    frame.agent,
                    frame.path(),
                    "event",
                    event="retry",
                    attempt=frame.attempt + 1,
                    outcome=event.name,
                )
            delay = self.timers.delay(state.retry_delay, frame, (*state.at, "retry", "delay"))
            if delay.__class__ is Event:
                return delay
            if delay:
                frame.retry_at = self.clock.tick + delay  # type: ignore[operator]
                return None
            self.next_attempt(frame)
            ended = self.start_call(frame, state, frame)
            if ended is None:
                return None
            event = ended
        return event

    def next_attempt(self, frame: Frame) -> None:
        """`state.attempt` grows as the behaviour is called again (docs/REFERENCE.md#retries), not during the
        delay."""
        frame.attempt += 1
        if frame.state.watches:
            self.clock.wake = True  # the watches read it next in the following tick: not to be skipped

    def _ended_once(self, frame: Frame, event: Event) -> None:
        """An attempt that will be retried: its error written down, or its outputs saved."""
        if event.name == "error":
            if not event.origin:
                event.origin = "/".join(frame.path())
                self.ledger.emit(frame.agent, frame.path(), "error", message=event.error)
            return
        if frame.state.save and event.outputs:
            save(frame, frame.state.save, event.outputs)
            if frame.state.watches:
                self.clock.wake = True  # a watch may read what the attempt saved

    @staticmethod
    def _count_of(times: Any, frame: Frame, what: str, where: Where) -> int | Event:
        if times.__class__ is int:
            return int(times)
        try:
            value = times(frame.scope)
        except ExprValueError as exc:
            return Event("error", error=f"retry {what}: {exc}", where=where)
        if value.__class__ is not int or value <= 0:
            message = f"retry times must be a positive whole number, not {value!r}"
            return Event("error", error=message, where=where)
        return int(value)
