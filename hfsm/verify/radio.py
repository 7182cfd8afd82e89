"""World `none` with a radio that may lose or delay what is sent: each post is a choice point."""

from __future__ import annotations

import copy
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm.primitive import Message
from hfsm.verify.choices import Decider
from hfsm.world import NOTICE, InputSpec, NullWorld


class Given:
    """The inputs' values and specs: the same in every state of a search, so shared by them (a
    state's copy holds a reference to it, `snapshot`)."""

    __slots__ = ("specs", "values")

    def __init__(self, values: Mapping[str, Any]) -> None:
        self.values = dict(values)
        self.specs = {
            n: InputSpec(n, type(v).__name__, "given to hfsm-verify") for n, v in self.values.items()
        }


class ChoosingWorld(NullWorld):
    """Messages and barrier notices: delivered in the next tick, up to `delay` ticks late, or lost
    while `loss` lasts. `fail` is how many agents may still fail (the search spends it)."""

    name = "none"

    def __init__(
        self,
        decider: Decider,
        loss: int,
        delay: int,
        fail: int,
        inputs: Mapping[str, Any] | Given | None = None,
    ) -> None:
        super().__init__()
        # in.NAME: one value for the whole run, for every agent
        self.given = inputs if isinstance(inputs, Given) else Given(inputs or {})
        self.decider = decider
        self.loss = loss
        self.delay = delay
        self.fail_left = fail
        self.n = 0  # choice points so far
        self.posted = 0
        self.tick = 0  # the engine's, set by whoever drives it
        self.flying: list[tuple[int, int, Message]] = []  # (tick it arrives in, order, message)

    def inputs(self) -> Mapping[str, InputSpec]:
        return self.given.specs

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        value = self.given.values[name]
        return copy.deepcopy(value) if isinstance(value, list | dict) else value  # every state's own

    def post(self, message: Message) -> None:
        options: list[dict[str, Any]] = [{"delay": d} for d in range(self.delay + 1)]
        if self.loss > 0:
            options.append({"lost": True})
        what = _what(message)
        chosen = self.decider.pick(self, message.sent_tick, "message", what, options)
        self.posted += 1
        if chosen.get("lost"):
            self.loss -= 1
            return
        arrives = message.sent_tick + 1 + int(chosen.get("delay", 0))
        self.flying.append((arrives, self.posted, message))

    def collect(self, tick: int) -> list[Message]:
        flying = self.flying
        if not flying:
            return []
        due = sorted((f for f in flying if f[0] <= tick), key=lambda f: (f[0], f[1]))
        if due:
            self.flying = [f for f in flying if f[0] > tick]
        return [m for _, _, m in due]

    def next_delivery(self) -> int | None:
        ticks = [t for t, _, m in self.flying if m.name != NOTICE]
        return min(ticks) if ticks else None

    def in_flight(self) -> Sequence[Message]:
        return [m for _, _, m in self.flying]


def _what(message: Message) -> str:
    if message.name == NOTICE:
        data = message.data
        kind = "answer" if data.get("answer") else "notice"
        return f"barrier {kind} '{data['barrier']}' round {data['round']} {message.sender}->{message.to}"
    return f"message '{message.name}' {message.sender}->{message.to}"
