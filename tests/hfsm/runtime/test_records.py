"""Records written as text (TextRecords, for a JSONL sink) are the bytes of the same records as dicts
(Records) encoded as the JSONL trace encodes them: any names, times, deadlines, nesting, regions."""

from __future__ import annotations

import math
from typing import Any

from hypothesis import given
from hypothesis import strategies as st

from hfsm.cli.tracefile import _finite
from hfsm.primitive import Message
from hfsm.runtime import records as records_module
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.records import Records, TextRecords
from hfsm.runtime.states import RMachine, RRegion, RState
from hfsm.trace import encode
from hfsm.world import NullWorld

NAMES = st.text(min_size=1, max_size=6) | st.sampled_from(['"', "\\", "\n", "é", "\U0001f600", "\x00", "a/b"])


class Clock:
    def __init__(self, tick: int, dt: float) -> None:
        self.tick = tick
        self.dt = dt

    @property
    def time(self) -> float:
        return round(self.tick * self.dt, 9)


class Both:
    """A sink that takes dicts and lines, and keeps what each call wrote as text, in order."""

    def __init__(self) -> None:
        self.text: list[str] = []

    def write(self, record: dict[str, Any]) -> None:
        self.text.append(encode(record) + "\n")

    def write_line(self, line: str) -> None:
        self.text.append(line)

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


def _state(name: str, machine: RMachine, do: str) -> RState:
    state = RState(name, machine)
    state.do = do
    return state


@st.composite
def frames(draw: st.DrawFn) -> list[Frame]:
    """A chain of running machines, some called from a region of a parallel state, with timers."""
    agent = Agent(draw(NAMES), draw(NAMES), None, 0, NullWorld())
    agent.clock = Clock(0, 0.05)
    chain: list[Frame] = []
    up: Frame | Region | None = None
    for _ in range(draw(st.integers(1, 4))):
        machine = RMachine(draw(NAMES), None)  # type: ignore[arg-type]
        machine.initial = _state(draw(NAMES), machine, draw(NAMES | st.just("")))
        frame = Frame(machine, {}, agent, up)
        frame.state_deadline = draw(st.none() | st.integers(0, 10**7))
        frame.deadline = draw(st.none() | st.integers(0, 10**7))
        frame.vars_shown = draw(st.booleans())
        chain.append(frame)
        up = Region(RRegion(draw(NAMES), 0), frame) if draw(st.booleans()) else frame
    return chain


@given(frames(), st.integers(0, 10**7), st.floats(1e-4, 10.0), NAMES, NAMES | st.none())
def test_text_records_are_the_dicts_bytes(
    chain: list[Frame], tick: int, dt: float, event: str, target: str | None
) -> None:
    written: list[list[str]] = []
    shown = [frame.vars_shown for frame in chain]
    for kind in (Records, TextRecords):
        for frame, was in zip(chain, shown, strict=True):
            frame.vars_shown = was
        sink = Both()
        clock = Clock(tick, dt)
        records = kind(sink, clock)
        for frame in chain:
            frame.text = None
            records.enter(frame, frame.state)
            records.arc(frame, frame.state, Event(event), target)
            records.arc(frame, frame.state, Event(event), frame.state)
            records.flush()  # the end of a tick
            clock.tick += 1
        written.append(sink.text)
    assert "".join(written[1]) == "".join(written[0])


class Lenient(Both):
    """Non-finite numbers as text, as the trace file writes them."""

    def write(self, record: dict[str, Any]) -> None:
        try:
            super().write(record)
        except ValueError:
            super().write(_finite(record))


VALUES = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats() | st.sampled_from([math.nan, math.inf]) | NAMES,
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(NAMES, inner, max_size=3),
    max_leaves=8,
)


@given(
    NAMES,
    st.lists(NAMES, min_size=1, max_size=3),
    st.lists(st.tuples(NAMES, NAMES, st.dictionaries(NAMES, VALUES, max_size=3), st.integers(1, 4)), max_size=4),
    st.integers(0, 10**6),
    st.sampled_from([2, 3, records_module.KEEP_MOST]),
)
def test_receive_records_are_the_dicts_bytes(
    agent_name: str, path: list[str], sends: list[tuple[str, str, dict[str, Any], int]], tick: int, most: int
) -> None:
    """A message said to many arrives as shallow copies of one dict, whose data is encoded once; any
    data (NaN and infinities go the sink's way), copies or not, gives the dicts' bytes."""
    agent = Agent(agent_name, path[0], None, 0, NullWorld())
    messages = [Message(name, sender, agent_name, dict(data), 0)
                for name, sender, data, copies in sends for _ in range(copies)]
    written: list[str] = []
    kept, records_module.KEEP_MOST = records_module.KEEP_MOST, most  # lines written within a tick, too
    try:
        for kind in (Records, TextRecords):
            sink = Lenient()
            clock = Clock(tick, 0.05)
            records = kind(sink, clock)
            for i, message in enumerate(messages):
                records.receive(agent, path, message)
                if i % 3 == 2:
                    records.flush()
                    clock.tick += 1
            records.flush()
            written.append("".join(sink.text))
    finally:
        records_module.KEEP_MOST = kept
    assert written[1] == written[0]
