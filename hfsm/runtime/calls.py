"""Calling a behaviour: a state's or a region's `with`, the callee started, a machine's end, retries."""

from __future__ import annotations

from typing import Any

from hfsm.expr import ExprValueError
from hfsm.runtime.agent import Event, Frame, Region
from hfsm.runtime.builtins import STARTERS, Wait
from hfsm.runtime.cancel import Cancelling
from hfsm.runtime.primitives import PrimitiveActivity, RunContext
from hfsm.runtime.program import RMachine, resolve_params, timer_ticks
from hfsm.runtime.states import Callee
from hfsm.spec import is_finite_number, shown

Where = tuple[str | int, ...]


class Calls(Cancelling):
    def _ticks(self, timer: Any, frame: Frame, where: Where = ()) -> int | Event:
        if timer.__class__ is int:
            return int(timer)
        takes = "a positive number of seconds"
        seconds = self._seconds(timer, frame, "timer", takes, zero=False, where=where)
        return seconds if isinstance(seconds, Event) else timer_ticks(seconds, self.dt)

    def _seconds(
        self, expr: Any, frame: Frame, what: str, takes: str, *, zero: bool, where: Where = ()
    ) -> float | Event:
        """A span given as an expression, checked: finite, and positive (or zero, if allowed).
        `where`: the expression's path in the machine file, for an error's position."""
        try:
            seconds = expr(frame.scope)
        except ExprValueError as exc:
            return Event("error", error=f"{what}: {exc}", where=(*where, *exc.where) if where else ())
        if not is_finite_number(seconds) or seconds < 0 or (seconds == 0 and not zero):
            return Event("error", error=f"{what} must be {takes}, not {shown(seconds)}", where=where)
        return float(seconds)

    def _params(self, callee: Callee, frame: Frame) -> dict[str, Any] | Event:
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

    def _start_call(self, frame: Frame, callee: Callee, where: Frame | Region) -> Event | None:
        """Start `callee` below `where` (a call state's frame, or a region of `frame`'s state).

        `with` reads `frame`. Returns what it ended with at once, or None while it runs.
        """
        if callee.wait_ticks:  # start_wait's work, without its calls
            where.below = Wait(self.tick + callee.wait_ticks)
            return None
        params = callee.params if callee.params is not None else self._params(callee, frame)
        if params.__class__ is Event:
            return params
        kind = callee.kind
        agent = frame.agent
        if kind == "machine":
            machine: RMachine = callee.callee  # type: ignore[assignment]
            child = where.below = Frame(machine, params, agent, where)  # type: ignore[arg-type]
            if machine.timer is None:  # _begin_machine's work, without its call
                ended = self._enter(child, machine.initial)  # type: ignore[arg-type]
                if ended is not None:
                    ended = self._run(child, ended)
            else:
                ended = self._begin_machine(child)
            if ended is not None:
                where.below = None
            return ended
        if kind == "primitive":
            starts = getattr(callee.callee, "start_activity", None)  # a stand-in of hfsm-verify
            if starts is not None:
                activity: Any = starts(self, agent, params, where)
            else:
                ctx = RunContext(self, agent, callee.do, where)
                activity = PrimitiveActivity(callee.callee, ctx, params, where)  # type: ignore[arg-type]
        else:
            activity = STARTERS[kind](self, agent, frame, params, where)  # type: ignore[arg-type]
            if activity.__class__ is Event:
                return activity
        event: Event | None = activity.advance(self.tick)
        if event is None:
            where.below = activity
        return event

    def _begin_machine(self, frame: Frame) -> Event | None:
        """A called machine starts: its timer, its initial state; its ending if it ends at once."""
        machine: RMachine = frame.machine
        if machine.timer is not None:
            ticks = self._ticks(machine.timer, frame)
            if ticks.__class__ is Event:
                ticks.origin = "/".join(frame.prefix())
                return ticks
            frame.deadline = self.tick + ticks  # type: ignore[operator]
        event = self._enter(frame, machine.initial)  # type: ignore[arg-type]
        return None if event is None else self._run(frame, event)

    def _finish(self, frame: Frame, outcome: str) -> Event:
        """`frame`'s machine ends in `outcome`: its outputs evaluated."""
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

    def _retry(self, frame: Frame, event: Event) -> Event | None:
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
            if self.trace is not None:
                self.emit(
                    frame.agent,
                    frame.path(),
                    "event",
                    event="retry",
                    attempt=frame.attempt + 1,
                    outcome=event.name,
                )
            delay = self._delay(state.retry_delay, frame, (*state.at, "retry", "delay"))
            if delay.__class__ is Event:
                return delay
            if delay:
                frame.retry_at = self.tick + delay  # type: ignore[operator]
                return None
            self._next_attempt(frame)
            ended = self._start_call(frame, state, frame)
            if ended is None:
                return None
            event = ended
        return event

    def _next_attempt(self, frame: Frame) -> None:
        """`state.attempt` grows as the behaviour is called again (docs/REFERENCE.md#retries), not during the
        delay."""
        frame.attempt += 1
        if frame.state.watches:
            self.wake = True  # the watches read it next in the following tick: not to be skipped

    def _ended_once(self, frame: Frame, event: Event) -> None:
        """An attempt that will be retried: its error written down, or its outputs saved."""
        if event.name == "error":
            if not event.origin:
                event.origin = "/".join(frame.path())
                self.emit(frame.agent, frame.path(), "error", message=event.error)
            return
        if frame.state.save and event.outputs:
            self._save(frame, frame.state.save, event.outputs)
            if frame.state.watches:
                self.wake = True  # a watch may read what the attempt saved

    def _count_of(self, times: Any, frame: Frame, what: str, where: Where) -> int | Event:
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

    def _delay(self, delay: Any, frame: Frame, where: Where) -> int | Event:
        if delay.__class__ is int:
            return int(delay)
        takes = "a number of seconds >= 0"
        seconds = self._seconds(delay, frame, "retry delay", takes, zero=True, where=where)
        return seconds if isinstance(seconds, Event) else max(0, self.span(seconds))
