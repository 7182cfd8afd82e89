"""Timers (docs/REFERENCE.md#time-and-timers): spans given as expressions made ticks, and what a
state's or a machine's timer does when it fires."""

from __future__ import annotations

from typing import Any

from hfsm.expr import ExprValueError
from hfsm.runtime.agent import Event, Frame
from hfsm.runtime.cancel import Cancelling
from hfsm.runtime.clock import RunClock
from hfsm.runtime.ledger import Ledger
from hfsm.runtime.parts import ArcsPart, CallsPart, HoldsPart
from hfsm.runtime.program import timer_ticks
from hfsm.spec import is_finite_number, shown

Where = tuple[str | int, ...]  # a path in a machine file


class Timers:
    arcs: ArcsPart
    calls: CallsPart
    holds: HoldsPart

    def __init__(self, clock: RunClock, ledger: Ledger, cancelling: Cancelling) -> None:
        self.clock = clock
        self.ledger = ledger
        self.cancelling = cancelling

    def ticks(self, timer: Any, frame: Frame, where: Where = ()) -> int | Event:
        if timer.__class__ is int:
            return int(timer)
        takes = "a positive number of seconds"
        seconds = self.seconds(timer, frame, "timer", takes, zero=False, where=where)
        return seconds if isinstance(seconds, Event) else timer_ticks(seconds, self.clock.dt)

    @staticmethod
    def seconds(
        expr: Any, frame: Frame, what: str, takes: str, *, zero: bool, where: Where = ()
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

    def delay(self, delay: Any, frame: Frame, where: Where) -> int | Event:
        if delay.__class__ is int:
            return int(delay)
        takes = "a number of seconds >= 0"
        seconds = self.seconds(delay, frame, "retry delay", takes, zero=True, where=where)
        return seconds if isinstance(seconds, Event) else max(0, self.clock.span(seconds))

    def state_timeout(self, frame: Frame) -> None:
        """The state's timer fired: its `timeout` arc taken, or held."""
        if frame.state.autonomy and self.holds.timer_held(frame):
            return
        self.ledger.emit(frame.agent, frame.path(), "timeout", timer="state")
        self.arcs.settle(frame, self.cancelling.cancelled(frame, "timeout", Event("timeout")))

    def machine_timeout(self, frame: Frame) -> None:
        self.ledger.emit(frame.agent, frame.prefix(), "timeout", timer="machine")
        problem = self.cancelling.cancel_below(frame, "timeout")
        if problem:
            self.arcs.settle(frame, Event("error", error=problem))
            return
        self.ledger.leave(frame, "timeout")
        self.arcs.pass_up(frame, self.calls.finish(frame, "timeout"))
