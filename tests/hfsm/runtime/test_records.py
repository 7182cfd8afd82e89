"""Records written as text (TextRecords, for a JSONL sink) are the bytes of the same records as dicts
(Records) encoded as the JSONL trace encodes them: any names, times, deadlines, nesting, regions."""

from __future__ import annotations

from typing import Any

from hypothesis import given
from hypothesis import strategies as st

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
