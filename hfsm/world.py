"""The world seam: what the interpreter needs of the world the agents act in.

`--world none` is `NullWorld`: a perfect radio and nothing else. The simulator plugs in through
the `hfsm.worlds` entry-point group (a `WorldFactory`), so hfsm never imports it.
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

from hfsm.primitive import Message

WORLDS_GROUP = "hfsm.worlds"
# the kind of the engine's own barrier notices: never a message name (docs/REFERENCE.md#barriers)
NOTICE = "barrier notice"


@dataclass(frozen=True)
class InputSpec:
    """An input a world declares (docs/REFERENCE.md#watches): machines read it as `in.NAME`."""

    name: str
    type: str  # int, float, bool, str, list or dict, as a param's type
    doc: str  # what it is, with its unit


NO_INPUTS: Mapping[str, InputSpec] = {}


class World(Protocol):
    """Advances time one tick for all agents and carries their messages."""

    name: str
    static: bool  # True: nothing changes between events, so idle ticks may be skipped
    default_trace: Path | None  # where the trace goes when --trace is not given (None: nowhere)

    def agent_names(self) -> Sequence[str] | None:
        """The agents this world has (e.g. a scenario's robots), or None to let the run choose."""

    def start(self, agents: Sequence[str], dt: float) -> None: ...

    def handle(self, agent: str) -> Any:
        """What primitives of that agent get as `ctx.robot`."""

    def inputs(self) -> Mapping[str, InputSpec]:
        """The inputs this world declares, by name."""

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        """A declared input's value for `agent` at `tick` (the engine asks at most once a tick)."""

    def post(self, message: Message) -> None: ...

    def collect(self, tick: int) -> list[Message]:
        """Messages that enter the mailboxes at the start of `tick`, in delivery order."""

    def next_delivery(self) -> int | None: ...

    def advance(self, tick: int) -> None:
        """Move the world from tick `tick` to tick `tick + 1`."""

    def failures(self, tick: int) -> Sequence[tuple[str, str]]:
        """The agents this world fails at the start of `tick`, each with the reason
        (docs/REFERENCE.md#agents-that-fail).

        A static world is never asked: one that fails agents on its own must not be static.
        """

    def fail(self, agent: str) -> None:
        """The agent failed (by this world or by `--fail`): its body stops, drops what it holds
        and goes silent."""

    def report(self) -> dict[str, Any]:
        """Extra top-level keys for `--json`, e.g. {"score": {...}}."""

    def close(self) -> list[str]:
        """Release resources; return the paths of files written (videos, pictures)."""


class WorldFactory(Protocol):
    name: str

    def add_arguments(self, group: argparse._ArgumentGroup) -> None: ...

    def inputs(self) -> Mapping[str, InputSpec]:
        """What its worlds declare, known before one is made (for `--check`)."""

    def create(self, args: argparse.Namespace, seed: int) -> World: ...

    # Optional: `check(args) -> None`, called by `hfsm-run --check` to check the world's own
    # flags (e.g. a scenario file) without making the world; raises UsageError.


class PerfectRadio:
    """Every message arrives at the start of the tick after it was sent, in sending order."""

    def __init__(self) -> None:
        self._in_flight: list[Message] = []

    def post(self, message: Message) -> None:
        self._in_flight.append(message)

    def collect(self, tick: int) -> list[Message]:
        if not self._in_flight:
            return []
        due = [m for m in self._in_flight if m.sent_tick < tick]
        self._in_flight = [m for m in self._in_flight if m.sent_tick >= tick]
        return due

    def next_delivery(self) -> int | None:
        """The next tick a message enters a mailbox (barrier notices never do)."""
        if not self._in_flight:
            return None
        ticks = [m.sent_tick for m in self._in_flight if m.name != NOTICE]
        return min(ticks) + 1 if ticks else None


class NullWorld(PerfectRadio):
    """`--world none`: built-in behaviours only, no simulator."""

    name = "none"
    static = True
    default_trace: Path | None = None

    def agent_names(self) -> Sequence[str] | None:
        return None

    def start(self, agents: Sequence[str], dt: float) -> None:
        pass

    def handle(self, agent: str) -> Any:
        return None

    def inputs(self) -> Mapping[str, InputSpec]:
        return NO_INPUTS

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        raise KeyError(f"world 'none' declares no input '{name}'")

    def advance(self, tick: int) -> None:
        pass

    def failures(self, tick: int) -> Sequence[tuple[str, str]]:
        return ()

    def fail(self, agent: str) -> None:
        pass

    def report(self) -> dict[str, Any]:
        return {}

    def close(self) -> list[str]:
        return []
