"""A run that a stop signal ends cleanly: the world's next delivery raises, the run loop cancels
everything and closes the trace, as for a fatal error."""

from __future__ import annotations

from typing import Any, cast

from hfsm.cli.guard import StopFlag
from hfsm.runtime.core import FatalError
from hfsm.world import World


class Interrupted(FatalError):
    """A signal asked the run to stop: ends it like a fatal error, so that everything is cancelled."""


class _StoppableWorld:
    """The world, but its mailbox delivery ends the run once a stop signal came."""

    def __init__(self, world: World, flag: StopFlag) -> None:
        self._world = world
        self._flag = flag

    def collect(self, tick: int) -> Any:
        if self._flag.signum is not None:
            raise Interrupted("", f"stopped by {self._flag.name}")
        return self._world.collect(tick)

    def stopping(self) -> bool:
        """Whether a stop signal came (a run that waits for its operator looks)."""
        return self._flag.signum is not None

    def __getattr__(self, name: str) -> Any:
        return getattr(self._world, name)


def stoppable(world: World, flag: StopFlag) -> World:
    return cast(World, _StoppableWorld(world, flag))
