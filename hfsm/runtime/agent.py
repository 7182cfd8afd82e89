"""An agent's run-time state: its stack of machine frames, its mailbox, its statistics."""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Any, Protocol

from hfsm.expr import Scope
from hfsm.primitive import Message
from hfsm.runtime.live import Clock, FrameLive, Inputs
from hfsm.runtime.program import RMachine, RState
from hfsm.world import World


class Event:
    """What ends a state: a callee's outcome (with outputs), a timeout, a message, an error, a choice."""

    __slots__ = ("error", "goto", "message", "name", "origin", "outputs", "traceback")

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
    ) -> None:
        self.name = name
        self.outputs = outputs
        self.error = error
        self.origin = origin
        self.traceback = traceback
        self.goto = goto
        self.message = message


class Activity(Protocol):
    """A running built-in or primitive: the leaf of an agent's stack."""

    deadline: int | None  # the tick it must next be advanced in; None: only when a message comes

    def advance(self, tick: int) -> Event | None: ...

    def cancel(self) -> None: ...


class Frame:
    """One running machine: its memory, its current state and its timers."""

    __slots__ = (
        "_scope", "activity", "agent", "attempt", "clock", "deadline", "entered", "machine", "params",
        "started", "state", "state_deadline", "vars",
    )  # fmt: skip

    def __init__(self, machine: RMachine, params: dict[str, Any], agent: Agent, clock: Clock) -> None:
        self.machine = machine
        self.params = params
        self.vars = machine.fresh_vars() if machine.var_init else {}
        self.agent = agent
        self.clock = clock
        self._scope: Scope | None = None
        self.state: RState = machine.initial  # type: ignore[assignment]
        self.deadline: int | None = None
        self.state_deadline: int | None = None
        self.started = clock.tick
        self.entered = 0
        self.attempt = 1
        self.activity: Activity | None = None

    @property
    def scope(self) -> Scope:
        """What expressions read; made on first use, since most frames never evaluate one."""
        if self._scope is None:
            live = FrameLive(self, self.clock, self.agent.inputs)
            self._scope = Scope(self.params, self.vars, self.agent.name, live)
        return self._scope


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
    failed: str | None = None  # the reason, when the agent failed (SPEC 15)


class Agent:
    def __init__(self, name: str, top: str, robot: Any, seed: int, world: World) -> None:
        self.name = name
        self.inputs = Inputs(world, name)
        self.top = top
        self.robot = robot
        self.rng = random.Random(f"{seed}:{name}")
        self.stack: list[Frame] = []
        self.mailbox: list[Message] = []
        self.stats: dict[str, BehaviourStats] = {}
        self.entries = 0
        self.started = False
        self.result: AgentResult | None = None
        self.failed: str | None = None  # the reason, once a world or --fail has failed it

    def path(self, level: int) -> list[str]:
        return [self.top, *(f.state.name for f in self.stack[: level + 1])]

    def take_message(self, names: Any) -> Message | None:
        """Remove and return the earliest message whose name is in `names`."""
        for i, message in enumerate(self.mailbox):
            if message.name in names:
                return self.mailbox.pop(i)
        return None

    def new_stats(self, behaviour: str) -> BehaviourStats:
        stats = self.stats[behaviour] = BehaviourStats()
        return stats
