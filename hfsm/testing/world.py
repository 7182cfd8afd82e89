"""The world of a behaviour test: world `none`'s perfect radio, plus scripted inputs and messages."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from hfsm.primitive import Message
from hfsm.runtime.program import span_ticks
from hfsm.testing.model import InputsAt, MessageIn, PartnerAt
from hfsm.testing.partners import ScriptedPartners
from hfsm.world import InputSpec, NullWorld

_TYPES = {bool: "bool", int: "int", float: "float", str: "str", list: "list", dict: "dict"}


def message_tick(at: float, dt: float) -> int:
    """The tick a scripted message enters the mailboxes: where a span of `at` s from tick 0 ends, at
    least tick 1 (the earliest any message can arrive: one sent in tick 0)."""
    return max(1, span_ticks(at, dt))


class ScriptedWorld(NullWorld):
    name = "test"

    def __init__(
        self,
        inputs: Sequence[InputsAt],
        messages: Sequence[MessageIn],
        agents: Sequence[str],
        dt: float,
        partners: Sequence[PartnerAt] = (),
    ) -> None:
        super().__init__()
        self.dt = dt
        self.partners = ScriptedPartners(partners, agents, dt) if partners else None
        # Entries in time order; among equal times, the file's order: the last that applies wins.
        self._inputs = sorted(inputs, key=lambda e: e.at)
        self._declared: dict[str, InputSpec] = {}
        for entry in self._inputs:
            for name, value in entry.in_.items():
                kind = "float" if type(value) is int else _TYPES.get(type(value), "str")
                self._declared.setdefault(name, InputSpec(name, kind, "scripted by the test"))
        # Reading an input each tick needs every tick run; without inputs idle ticks may be skipped.
        self.static = not self._inputs
        self._scripted: list[tuple[int, int, Message]] = []
        for i, m in enumerate(messages):
            tick = message_tick(m.at, dt)
            targets = [m.to] if m.to is not None else [a for a in agents if a != m.from_]
            for to in targets:
                self._scripted.append((tick, i, Message(m.qualified, m.from_, to, dict(m.data), tick - 1)))
        self._scripted.sort(key=lambda item: (item[0], item[1]))

    def inputs(self) -> Mapping[str, InputSpec]:
        return self._declared

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        now = round(tick * self.dt, 9)
        found, value = False, None
        for entry in self._inputs:
            if entry.at > now + 1e-9:
                break
            if name in entry.in_ and entry.agent in (None, agent):
                found, value = True, entry.in_[name]
        if not found:
            raise KeyError(f"the test gives no value before t={now:g} s")
        return value

    def post(self, message: Message) -> None:
        if self.partners is None or message.to not in self.partners.names():
            super().post(message)  # a partner's notices are scripted: what is sent to it is not needed

    def collect(self, tick: int) -> list[Message]:
        due = super().collect(tick)
        if self.partners is not None:
            due = self.partners.notices(tick) + due
        if self._scripted and self._scripted[0][0] <= tick:
            scripted = [m for t, _, m in self._scripted if t <= tick]
            self._scripted = [item for item in self._scripted if item[0] > tick]
            due = scripted + due
        return due

    def next_delivery(self) -> int | None:
        radio = super().next_delivery()
        scripted = self._scripted[0][0] if self._scripted else None
        if radio is None:
            return scripted
        return radio if scripted is None else min(radio, scripted)
