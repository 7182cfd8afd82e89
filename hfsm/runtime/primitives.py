"""Primitives run in greenlets: blocking calls for their authors, cancellable at any tick."""

from __future__ import annotations

import logging
import math
import sys
import traceback
from collections.abc import Callable
from typing import Any

from greenlet import GreenletExit, greenlet

from hfsm.names import KEEP
from hfsm.primitive import Cancelled, Message, Outcome, Primitive
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.runtime.program import span_ticks
from hfsm.runtime.scopes import radio_at

_KEPT_WAITING = object()  # what a cancelled primitive hands back when it waits again


class RunContext:
    """The `hfsm.primitive.Context` a primitive gets: clock, agent, mailbox, world handle, logger."""

    def __init__(self, host: Host, agent: Agent, behaviour: str, where: Frame | Region) -> None:
        self._host = host
        self._agent = agent
        self._where = where
        self.agent = agent.name
        self.robot = agent.robot
        self.dt = host.dt
        self.rng = agent.rng
        self.log = logging.getLogger(f"hfsm.{agent.name}.{behaviour}")
        self.cancelled = False

    @property
    def tick(self) -> int:
        return self._host.tick

    @property
    def time(self) -> float:
        return self._host.time

    def wait(self, seconds: float | None = None) -> None:
        hub = greenlet.getcurrent().parent
        if hub is None:
            raise RuntimeError("ctx.wait() called outside a running primitive")
        if self.cancelled:
            hub.switch(_KEPT_WAITING)  # it caught Cancelled and waits on: the engine ends it
        if seconds is not None and seconds <= 0:
            return
        if seconds is None:
            resume = self._host.tick + 1
        elif math.isfinite(seconds):
            resume = self._host.tick + span_ticks(seconds, self.dt)
        else:
            resume = sys.maxsize
        hub.switch(resume)

    def wait_until(self, ready: Callable[[], bool], timeout: float = math.inf) -> bool:
        end = self._host.tick + span_ticks(timeout, self.dt) if math.isfinite(timeout) else None
        while not ready():
            if end is not None and self._host.tick >= end:
                return False
            self.wait()
        return True

    @property
    def scope(self) -> str:
        return radio_at(self._where).name

    def receive(self, name: str) -> Message | None:
        return self._agent.take_message((name,), radio_at(self._where).prefix)

    def send(self, message: str, to: str = "others", *, keep: str = "all", **data: Any) -> None:
        if keep not in KEEP:  # the primitive's error, at its line
            raise ValueError(f"send: keep must be 'all' or 'last', not {keep!r}")
        self._host.send(self._agent, self._where, message, to, data, keep)


class PrimitiveActivity:
    def __init__(
        self, prim: Primitive, ctx: RunContext, params: dict[str, Any], where: Frame | Region
    ) -> None:
        self.prim = prim
        self.ctx = ctx
        self.where = where
        self.deadline: int | None = None
        self._g = greenlet(lambda: prim.fn(ctx, **params))

    def advance(self, tick: int) -> Event | None:
        try:
            value = self._g.switch()
        except Exception as exc:
            text = f"{type(exc).__name__}: {exc}"
            return Event("error", error=text, origin=self._origin(), traceback=traceback.format_exc())
        if not self._g.dead:
            self.deadline = value
            return None
        return self._result(value)

    def _origin(self) -> str:
        return "/".join(self.where.path())

    def _result(self, value: Any) -> Event:
        spec = self.prim.spec
        name, outputs = (value.name, dict(value.outputs)) if isinstance(value, Outcome) else (value, {})
        if not isinstance(name, str) or name not in spec.outcomes:
            error = f"'{spec.name}' returned {value!r}, not one of its outcomes ({', '.join(spec.outcomes)})"
            return Event("error", error=error, origin=self._origin())
        undeclared = set(outputs) - set(spec.outputs or ())
        if spec.outputs is not None and undeclared:
            error = f"'{spec.name}' returned undeclared outputs {sorted(undeclared)}"
            return Event("error", error=error, origin=self._origin())
        return Event(name, outputs)

    def cancel(self) -> str:
        """Raise `Cancelled` at its blocking call; one that catches it and goes on is ended all the same."""
        if self._g.dead:
            return ""
        self.ctx.cancelled = True
        if not self._g:  # never started
            return ""
        try:
            self._g.throw(Cancelled())
        except Cancelled:
            return ""
        except Exception:
            self.ctx.log.exception("primitive failed while cleaning up after a cancel")
            return ""
        if not self._g.dead:
            self._g.throw(GreenletExit())
            how = "waited again"
        else:
            how = "returned"
        return f"primitive '{self.prim.spec.name}' swallowed its cancellation (it caught Cancelled and {how})"
