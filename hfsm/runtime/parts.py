"""What the engine's parts ask of one another (runtime/engine.py composes them). A part names here
what it uses of a part it cannot import without an import circle: the calls between them go both
ways (a call enters states, a state's entry starts a call)."""

from __future__ import annotations

from typing import Protocol

from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.states import Callee, RState


class ArcsPart(Protocol):
    """runtime/arcs.py: events taken, states entered, machines' endings passed up."""

    def settle(self, frame: Frame, event: Event) -> None: ...

    def pass_up(self, frame: Frame, ended: Event) -> None: ...

    def run(self, frame: Frame, event: Event) -> Event | None: ...

    def enter(self, frame: Frame, state: RState) -> Event | None: ...

    def watch(self, frame: Frame, state: RState) -> Event | None: ...


class CallsPart(Protocol):
    """runtime/calls.py: behaviours started, machines begun and finished, retries."""

    def start_call(self, frame: Frame, callee: Callee, where: Frame | Region) -> Event | None: ...

    def begin_machine(self, frame: Frame) -> Event | None: ...

    def finish(self, frame: Frame, outcome: str) -> Event: ...

    def retry(self, frame: Frame, event: Event) -> Event | None: ...

    def next_attempt(self, frame: Frame) -> None: ...


class RegionsPart(Protocol):
    """runtime/parallel.py: the regions of parallel states."""

    def start_regions(self, frame: Frame) -> Event | None: ...

    def step_regions(self, frame: Frame, regions: list[Region]) -> None: ...

    def region_ended(self, region: Region, event: Event) -> None: ...

    def region_failed(self, frame: Frame, event: Event) -> Event: ...

    def join(self, frame: Frame, regions: list[Region]) -> Event | None: ...


class HoldsPart(Protocol):
    """runtime/holds.py: arcs held for the operator."""

    def held(self, frame: Frame, state: RState, event: Event) -> bool: ...

    def timer_held(self, frame: Frame) -> bool: ...

    def message_held(self, frame: Frame, state: RState) -> bool: ...


class LoopPart(Protocol):
    """runtime/loop.py: an agent's turn in a tick, and its end."""

    def step(self, frame: Frame) -> None: ...

    def end_agent(self, agent: Agent, event: Event) -> None: ...
