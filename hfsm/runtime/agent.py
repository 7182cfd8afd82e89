"""An agent's run-time state: a tree of running machines and regions, its mailbox, its statistics.

A `Frame` is one running machine; below its current state runs one thing: an activity (a built-in
or a primitive), another frame (a called machine), or, in a parallel state, a list of `Region`s,
each running an activity or a frame of its own. Frames and regions know who runs them (`up`,
`owner`), so paths and endings are found by walking up, never by counting levels.
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any, Protocol

from hfsm.expr import Scope
from hfsm.primitive import Message
from hfsm.runtime.live import Clock, FrameLive, Inputs
from hfsm.runtime.mailbox import Mailbox
from hfsm.runtime.scopes import Radio
from hfsm.runtime.states import RMachine, RRegion, RState
from hfsm.world import World

CALLEE = "<callee>"  # an Event's `where` that starts so is a path in the file of the machine run at `origin`


class Event:
    """What ends a state: a callee's outcome (with outputs), a timeout, a message, an error, a choice."""

    __slots__ = ("error", "goto", "message", "name", "origin", "outputs", "traceback", "where")

    def __init__(
        self,
        name: str,
        outputs: dict[str, Any] | None = None,
        *,
        error: str = "",
        origin: str = "",
        traceback: str = "",
        goto: RState | str | None = None,
        message: Message | None = None,
        where: tuple[str | int, ...] = (),
    ) -> None:
        self.name = name
        self.outputs = outputs
        self.error = error
        self.origin = origin
        self.traceback = traceback
        self.goto = goto
        self.message = message
        self.where = where  # an error's expression: its path in the machine file of the state at `origin`


HELD = Event("held")  # a state entered holds an arc at once: it waits, nothing is taken


class Activity(Protocol):
    """A running built-in or primitive: a leaf of an agent's tree."""

    deadline: int | None  # the tick it must next be advanced in; None: only when a message comes

    def advance(self, tick: int) -> Event | None: ...

    def cancel(self) -> str:
        """Stop at once, cleaning up; a problem as text (e.g. the cancel was swallowed), or ''."""


class Frame:
    """One running machine: its memory, its current state, its timers, and what runs below it."""

    __slots__ = (
        "_prefix", "_scope", "agent", "attempt", "below", "deadline", "entered", "held", "in_with", "inner",
        "machine", "params", "radio", "retry_at", "started", "state", "state_deadline", "text", "up",
        "vars", "vars_new", "vars_shown",
    )  # fmt: skip
    entered: int  # the tick its current state was entered (set on entering it, as the two below)
    state_deadline: int | None
    attempt: int  # the call of that state's behaviour, from 1 (docs/REFERENCE.md#retries)
    radio: Radio  # the scope its machine runs under (docs/REFERENCE.md#scopes)
    inner: Radio  # the scope its current state gives what it runs: `radio`, or the state's `scope:`

    def __init__(
        self, machine: RMachine, params: dict[str, Any], agent: Agent, up: Frame | Region | None
    ) -> None:
        self.machine = machine
        self.params = params
        self.vars = machine.fresh_vars() if machine.var_init else {}
        self.vars_shown = not self.vars or machine.untraced.issuperset(self.vars)
        # while not vars_shown: the vars changed since (None: all); sorted, as Team.fresh
        self.vars_new: dict[str, None] | None = None
        self.agent = agent
        self.up = up
        self._scope: Scope | None = None
        self._prefix: tuple[str, ...] | None = None
        self.text: Any = None  # where it runs, as the trace's TextRecords writes it (a Prefix)
        self.state: RState = machine.initial  # type: ignore[assignment]
        self.deadline: int | None = None  # the machine timer's tick
        self.retry_at: int | None = None  # the tick a retry's delay ends in
        self.started = agent.clock.tick
        self.below: Any = None  # Activity | Frame | list[Region] | None
        if up is None:
            self.radio = agent.radio
        else:
            self.radio = up.inner if isinstance(up, Frame) else up.owner.inner
        self.inner = self.radio
        self.in_with = False  # a state's `with` being read: `scope.*` is the state's own scope
        self.held: Any = None  # the arc its state holds for the operator (a holds.Hold)

    def changed(self, names: Iterable[str]) -> None:
        """Vars just assigned: the trace's next record of this machine shows them (unless untraced)."""
        quiet = self.machine.untraced
        new = [n for n in names if n not in quiet] if quiet else names
        if self.vars_shown:
            self.vars_new = dict.fromkeys(sorted(new))
            self.vars_shown = not self.vars_new
        elif self.vars_new is not None:
            self.vars_new = dict.fromkeys(sorted({*self.vars_new, *new}))

    @property
    def scope(self) -> Scope:
        """What expressions read; made on first use, since most frames never evaluate one."""
        if self._scope is None:
            live = FrameLive(self, self.agent.clock, self.agent.inputs)
            self._scope = Scope(self.params, self.vars, self.agent.name, live)
        return self._scope

    def prefix(self) -> list[str]:
        """The path of the state or region that runs this machine."""
        return list(self._prefix or self._own_prefix())

    def path(self) -> list[str]:
        """The path of this machine's current state."""
        return [*(self._prefix or self._own_prefix()), self.state.name]

    def _own_prefix(self) -> tuple[str, ...]:
        """Made once: what runs a machine stays where it is while the machine runs (trace records)."""
        up = self.up
        self._prefix = (self.agent.top,) if up is None else tuple(up.path())
        return self._prefix


class Region:
    """One region of a running parallel state; `result` is set when its behaviour ends."""

    __slots__ = ("below", "owner", "result", "spec")

    def __init__(self, spec: RRegion, owner: Frame) -> None:
        self.spec = spec
        self.owner = owner
        self.below: Any = None  # Activity | Frame | None
        self.result: Event | None = None

    def path(self) -> list[str]:
        return [*self.owner.path(), self.spec.name]


def frames(frame: Frame) -> Iterator[Frame]:
    """Every running machine frame at and below `frame`, outermost first, regions in their order."""
    yield frame
    below = frame.below
    if below.__class__ is Frame:
        yield from frames(below)
    elif below.__class__ is list:
        for region in below:
            if region.below.__class__ is Frame:
                yield from frames(region.below)


def leaves(frame: Frame) -> Iterator[Frame | Region]:
    """The innermost running frames and regions below `frame`, in region order."""
    below = frame.below
    if below.__class__ is Frame:
        yield from leaves(below)
    elif below.__class__ is list and any(r.result is None for r in below):
        for region in below:
            if region.result is None:
                if region.below.__class__ is Frame:
                    yield from leaves(region.below)
                else:
                    yield region
    else:
        yield frame


@dataclass
class BehaviourStats:
    calls: int = 0
    ticks: int = 0
    events: dict[str, int] = field(default_factory=dict)


@dataclass
class AgentResult:
    outcome: str | None
    outputs: dict[str, Any]
    time: float
    failed: str | None = None  # the reason, when the agent failed (docs/REFERENCE.md#agents-that-fail)


class _NoClock:
    tick = 0
    dt = 0.0


_NO_CLOCK: Clock = _NoClock()


class Agent:
    def __init__(self, name: str, top: str, robot: Any, seed: int, world: World) -> None:
        self.name = name
        self.top = top
        self.robot = robot
        self.rng = random.Random(f"{seed}:{name}")
        self.inputs = Inputs(world, name)
        self.clock: Clock = _NO_CLOCK  # the engine's, once it runs
        self.root: Frame | None = None
        self.mailbox = Mailbox()
        self.radio = Radio("", (), top=True)  # outside every scope: set with the run's agents
        self.stats: dict[str, BehaviourStats] = {}
        self.entries = 0
        self.started = False
        self.result: AgentResult | None = None
        self.failed: str | None = None  # the reason, once a world or --fail has failed it

    def where(self) -> str:
        """Each innermost running state's path, for messages about an agent that has not ended."""
        if self.root is None:
            return self.top
        return ", ".join("/".join(leaf.path()) for leaf in leaves(self.root))

    def take_message(self, names: Any, prefix: str = "") -> Message | None:
        """Remove and return the earliest message whose name is in `names`, sent under the scope
        whose names begin with `prefix`: `scope/name`, or a bare name outside every scope."""
        return self.mailbox.take(names, prefix)

    def new_stats(self, behaviour: str) -> BehaviourStats:
        stats = self.stats[behaviour] = BehaviourStats()
        return stats
