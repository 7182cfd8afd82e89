"""The trace records a running engine writes (SPEC 10): as dicts for any sink, or as JSON text.

`Records` builds every record as a dict and hands it to the sink's `write`. `TextRecords` serves a
sink that also takes lines (`write_line`, such as `JsonlTrace`): the records written on every
transition (`enter`, and `event` with its `exit`) are written as text from pieces made once (the
agent's name and the tick's time, a frame's path, names as JSON strings), the same bytes as the
sink's own encoding of the dict; a record holding a user's values (vars, a barrier's `arrived`)
and every other kind still go through `write`.
"""

from __future__ import annotations

from json.encoder import encode_basestring
from typing import Any, Protocol

from hfsm.runtime.agent import Agent, Event, Frame
from hfsm.runtime.states import RState
from hfsm.trace import TraceSink, encode


class LineSink(TraceSink, Protocol):
    def write_line(self, line: str) -> None:
        """Record(s) already encoded, each line ended by a newline: the bytes `write` would give."""


class TraceClock(Protocol):
    tick: int
    dt: float

    @property
    def time(self) -> float:
        """Seconds at this tick, as the trace shows them."""


class Records:
    def __init__(self, sink: TraceSink, clock: TraceClock) -> None:
        self.sink = sink
        self.clock = clock

    def write(self, agent: Agent, path: list[str], kind: str, **extra: Any) -> None:
        self.sink.write({"t": self.clock.time, "agent": agent.name, "path": path, "kind": kind, **extra})

    def enter(self, frame: Frame, state: RState) -> None:
        """A state entered: its callee, when the state's and the machine's timers fire (seconds),
        and the machine's vars when the trace has not shown them since they changed."""
        extra: dict[str, Any] = {"do": state.do} if state.do else {}
        dt = self.clock.dt
        if frame.state_deadline is not None:
            extra["deadline"] = round(frame.state_deadline * dt, 9)
        if frame.deadline is not None:
            extra["machine_deadline"] = round(frame.deadline * dt, 9)
        extra.update(self.vars_of(frame))
        self.write(frame.agent, frame.path(), "enter", **extra)

    def arc(self, frame: Frame, state: RState, event: Event, target: RState | str | None) -> None:
        """An event taken by `frame`'s state (its arc's target) and the state's exit."""
        shown = target.name if target.__class__ is RState else target
        extra = self.vars_of(frame)
        if state.do == "barrier" and event.outputs:
            extra["arrived"] = event.outputs.get("arrived")  # who the barrier heard (the monitor)
        self.write(frame.agent, frame.path(), "event", event=event.name, target=shown, **extra)
        self.write(frame.agent, frame.path(), "exit", event=event.name)

    @staticmethod
    def vars_of(frame: Frame) -> dict[str, Any]:
        """`{"vars": {...}}` once after the machine's vars change (a trace shows values on change)."""
        if frame.vars_shown:
            return {}
        frame.vars_shown = True
        return {"vars": dict(frame.vars)}


class _Json(dict[Any, str]):
    """Names (and other constants) as JSON text, each encoded once."""

    def __missing__(self, key: Any) -> str:
        text = self[key] = encode_basestring(key) if key.__class__ is str else encode(key)
        return text


def seconds_text(ticks: int, dt: float) -> str:
    """`encode(round(ticks * dt, 9))`: a tick's time in seconds (as Core.time) as JSON text.

    `round` and `f"{x:.9f}"` make the same correctly rounded 9 decimals; from 1e-4 to 1e6 s they have
    at most 15 digits, so `repr` of the rounded float writes them back, without an exponent: the
    rounding's float and its `repr` are not needed (half the cost)."""
    x = ticks * dt
    if 1e-4 <= x < 1e6:
        text = f"{x:.9f}".rstrip("0")
        return text + "0" if text[-1] == "." else text
    return float.__repr__(round(x, 9))


class TextRecords(Records):
    def __init__(self, sink: LineSink, clock: TraceClock) -> None:
        super().__init__(sink, clock)
        self.line = sink.write_line
        self.json = _Json()
        self.enters: dict[RState, str] = {}  # a state's `"name"], "kind": "enter", "do": …`
        self.arcs: dict[RState, dict[str, tuple[Any, str, str]]] = {}  # event -> target, the ends
        self.agent: Agent | None = None  # whose head was made last, and in which tick
        self.tick = -1
        self.head = ""
        self.shown: tuple[int | None, int | None] = (None, None)  # the last deadlines made, as text:
        self.shown_text = ""
        self.state_deadline: int | None = None  # the same, for a quick look
        self.deadline: int | None = None

    def _head(self, agent: Agent) -> str:
        """`{"t": …, "agent": …, "path": [` of `agent` in this tick."""
        self.agent = agent
        tick = self.tick = self.clock.tick
        x = tick * self.clock.dt
        if 1e-4 <= x < 1e6:  # seconds_text's quick way, without its call
            t = f"{x:.9f}".rstrip("0")
            t = t + "0" if t[-1] == "." else t
        else:
            t = seconds_text(tick, self.clock.dt)
        self.head = f'{{"t": {t}, "agent": {self.json[agent.name]}, "path": ['
        return self.head

    def _prefix(self, frame: Frame) -> str:
        """The JSON of the path of what runs `frame`, and ', ': made once a frame."""
        up = frame.up
        json = self.json
        if up is None:
            text = json[frame.agent.top] + ", "
        elif isinstance(up, Frame):
            text = f"{up.text or self._prefix(up)}{json[up.state.name]}, "
        else:  # a region's: its owner's path and its name
            owner = up.owner
            text = f"{owner.text or self._prefix(owner)}{json[owner.state.name]}, {json[up.spec.name]}, "
        frame.text = text
        return text

    def _enter_end(self, state: RState) -> str:
        json = self.json
        text = f'{json[state.name]}], "kind": "enter"' + (f', "do": {json[state.do]}' if state.do else "")
        self.enters[state] = text
        return text

    def _deadlines(self, frame: Frame) -> str:
        """`, "deadline": …, "machine_deadline": …` (those set); the last one made is kept."""
        shown = self.state_deadline, self.deadline = frame.state_deadline, frame.deadline
        if shown != self.shown:
            dt = self.clock.dt
            self.shown = shown
            self.shown_text = "".join(
                f', "{name}": {seconds_text(tick, dt)}'
                for name, tick in zip(("deadline", "machine_deadline"), shown, strict=True)
                if tick is not None
            )
        return self.shown_text

    def _arc_ends(self, state: RState, event: str, target: Any) -> tuple[Any, str, str]:
        json = self.json
        name, shown = json[event], json[target.name if target.__class__ is RState else target]
        ends = self.arcs.setdefault(state, {})[event] = (
            target,
            f'{json[state.name]}], "kind": "event", "event": {name}, "target": {shown}}}\n',
            f'{json[state.name]}], "kind": "exit", "event": {name}}}\n',
        )
        return ends

    def enter(self, frame: Frame, state: RState) -> None:
        if not frame.vars_shown:
            super().enter(frame, state)
            return
        agent = frame.agent
        head = self.head if agent is self.agent and self.tick == self.clock.tick else self._head(agent)
        end = self.enters.get(state) or self._enter_end(state)
        if frame.deadline is None and frame.state_deadline is None:
            self.line(f"{head}{frame.text or self._prefix(frame)}{end}}}\n")
            return
        if frame.deadline == self.deadline and frame.state_deadline == self.state_deadline:
            deadlines = self.shown_text
        else:
            deadlines = self._deadlines(frame)
        self.line(f"{head}{frame.text or self._prefix(frame)}{end}{deadlines}}}\n")

    def arc(self, frame: Frame, state: RState, event: Event, target: RState | str | None) -> None:
        if not frame.vars_shown or (state.do == "barrier" and event.outputs):
            super().arc(frame, state, event, target)
            return
        agent = frame.agent
        head = self.head if agent is self.agent and self.tick == self.clock.tick else self._head(agent)
        ends = self.arcs.get(state, _NONE).get(event.name)
        if ends is None or ends[0] is not target:
            ends = self._arc_ends(state, event.name, target)
        path = f"{head}{frame.text or self._prefix(frame)}"
        self.line(f"{path}{ends[1]}{path}{ends[2]}")


_NONE: dict[str, tuple[Any, str, str]] = {}


def records_for(sink: TraceSink | None, clock: TraceClock) -> Records | None:
    if sink is None:
        return None
    if hasattr(sink, "write_line"):
        return TextRecords(sink, clock)  # type: ignore[arg-type]
    return Records(sink, clock)
