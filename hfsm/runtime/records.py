"""The trace records a running engine writes (docs/REFERENCE.md#the-trace): as dicts for any sink, or as JSON
text.

`Records` builds every record as a dict and hands it to the sink's `write`. `TextRecords` serves a
sink that also takes lines (`write_line`, such as `JsonlTrace`): the records written on every
transition (`enter`, and `event` with its `exit`) are kept as text made once (`Prefix`: everything
of a record but its time, for each place a machine runs, state and event), and written at the end of
the tick, all its lines with the tick's time at once: the same bytes as the sink's own encoding of
the dicts. A record holding a user's values (vars, a barrier's `arrived`) and every other kind still
go through `write`, after the lines kept before them.
"""

from __future__ import annotations

from json.encoder import encode_basestring
from typing import Any, Protocol

from hfsm.primitive import Message
from hfsm.runtime.agent import Agent, Event, Frame
from hfsm.runtime.states import RRegion, RState
from hfsm.runtime.ticktime import TickTimes, seconds_text
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

    def receive(self, agent: Agent, path: list[str], message: Message, replaced: bool = False) -> None:
        """A message entered `agent`'s mailbox (`path`: where the agent runs); `replaced`: in place of
        the sender's copy not yet taken (`keep: last`)."""
        extra: dict[str, Any] = {"id": message.id} if message.id else {"data": message.data}
        if replaced:
            extra["replaced"] = True
        self.write(agent, path, "receive", message=message.name, sender=message.sender, **extra)

    def put(self, record: dict[str, Any]) -> None:
        """A record made elsewhere (a world's), written as it is."""
        self.sink.write(record)

    def flush(self) -> None:
        """The end of a tick that wrote something (or of the run): the sink's flush."""
        self.sink.flush()

    def drain(self) -> None:
        """Nothing kept back: the lines kept go to the sink, without its flush (the start's tick, whose
        flush is the next tick's, and the end of the run, whose sink is closed by whoever opened it)."""

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
        if state.traced and event.outputs:
            for name in state.traced:  # e.g. who a barrier heard (the monitor shows it)
                extra[name] = event.outputs.get(name)
        self.write(frame.agent, frame.path(), "event", event=event.name, target=shown, **extra)
        self.write(frame.agent, frame.path(), "exit", event=event.name)

    @staticmethod
    def vars_of(frame: Frame) -> dict[str, Any]:
        """`{"vars": {...}}` with the vars changed since the trace last showed them (all at first),
        once after they change; a machine's `untraced` vars are never shown."""
        if frame.vars_shown:
            return {}
        frame.vars_shown = True
        new, frame.vars_new = frame.vars_new, None  # None while shown: a copy's bytes stay the same
        values, quiet = frame.vars, frame.machine.untraced
        if new is None:
            return {"vars": {k: v for k, v in values.items() if k not in quiet} if quiet else dict(values)}
        return {"vars": {k: values[k] for k in values if k in new}}


class _Json(dict[Any, str]):
    """Names (and other constants) as JSON text, each encoded once."""

    def __missing__(self, key: Any) -> str:
        text = self[key] = encode_basestring(key) if key.__class__ is str else encode(key)
        return text


class Prefix:
    """One place where machines run (an agent's top, or a state or region below another place):
    the text of its records after their time, made once and shared by every frame run there."""

    __slots__ = ("arcs", "below", "enters", "head", "json")

    def __init__(self, head: str, json: _Json) -> None:
        self.head = head  # `, "agent": …, "path": [… , ` (the path up to the state)
        self.json = json
        self.enters: dict[RState, tuple[str, str]] = {}  # state -> `…, "kind": "enter", "do": …`, ended
        self.arcs: dict[RState, dict[str, tuple[Any, tuple[str, str]]]] = {}  # event -> target, lines
        self.below: dict[RState | RRegion, Prefix] = {}

    def inner(self, where: RState | RRegion, name: str) -> Prefix:
        """The place below this one's state or region `where` (named `name` in paths)."""
        inner = self.below[where] = Prefix(f"{self.head}{self.json[name]}, ", self.json)
        return inner

    def enter(self, state: RState) -> tuple[str, str]:
        """A state's `enter` line without its deadlines and its end; and ended."""
        json = self.json
        do = f', "do": {json[state.do]}' if state.do else ""
        text = f'{self.head}{json[state.name]}], "kind": "enter"{do}'
        pair = self.enters[state] = text, text + _END
        return pair

    def arc(self, state: RState, event: str, target: Any) -> tuple[Any, tuple[str, str]]:
        """The `event` and `exit` lines of an arc (kept, but for a callee's whose outputs are traced:
        those lines vary)."""
        json = self.json
        name, shown = json[event], json[target.name if target.__class__ is RState else target]
        path = f"{self.head}{json[state.name]}]"
        lines = (
            f'{path}, "kind": "event", "event": {name}, "target": {shown}' + _END,
            f'{path}, "kind": "exit", "event": {name}' + _END,
        )
        if not state.traced:
            self.arcs.setdefault(state, {})[event] = (target, lines)
        return target, lines


class TextRecords(Records):
    """Keeps the lines of the tick's transitions; `flush` (at the end of every tick, before the clock
    moves on) writes them with the tick's time, as does any other record written before them."""

    def __init__(self, sink: LineSink, clock: TraceClock) -> None:
        super().__init__(sink, clock)
        self.line = sink.write_line
        self.sink_flush = sink.flush
        self.json = _Json()
        self.tops: dict[Agent, Prefix] = {}
        self.kept: list[str] = []  # lines of this tick, without their `{"t": …`
        self.keep = self.kept.append
        self.times = TickTimes(clock.dt)
        self.heads: list[str] = []  # `{"t": …` of the ticks from `first` on (as many as were quick)
        self.first = 0
        self.shown: tuple[int | None, int | None] = (None, None)  # the last deadlines made, as text:
        self.shown_text = _END
        self.state_deadline: int | None = None  # the same, for a quick look
        self.deadline: int | None = None
        self.last_data: tuple[Any, str] | None = None  # a message's data, and as JSON

    def _head(self, tick: int) -> str:
        """`{"t": …` of `tick`, with those of the next ticks: twice as many as last time when the
        ticks come one after the other (64 at most), else one."""
        heads, first = self.heads, self.first
        count = min(2 * len(heads), 64) if heads and tick == first + len(heads) else 1
        self.heads, self.first = self.times.heads(tick, count), tick
        return self.heads[0]

    def _write_kept(self) -> None:
        """The lines kept, with the tick's time, to the sink."""
        tick = self.clock.tick
        at = tick - self.first
        head = self.heads[at] if 0 <= at < len(self.heads) else self._head(tick)
        self.line(head)
        self.line(head.join(self.kept))
        self.kept.clear()

    def write(self, agent: Agent, path: list[str], kind: str, **extra: Any) -> None:
        if self.kept:
            self._write_kept()
        super().write(agent, path, kind, **extra)

    def receive(self, agent: Agent, path: list[str], message: Message, replaced: bool = False) -> None:
        """Kept as a line: the number of its `send` record, or its data when it has none (encoded once
        for the copies of one dict that arrive in a row within a tick)."""
        json = self.json
        if message.id:
            said = f'"id": {message.id}'
        else:
            data, last = message.data, self.last_data
            if last is not None and _copies(data, last[0]):
                text = last[1]
            else:
                try:
                    text = encode(data)
                except ValueError:  # NaN or an infinity: the sink's own way
                    super().receive(agent, path, message, replaced)
                    return
                self.last_data = (data, text)
            said = f'"data": {text}'
        where = ", ".join([json[name] for name in path])
        self.keep(f', "agent": {json[agent.name]}, "path": [{where}], "kind": "receive", "message": '
                  f'{json[message.name]}, "sender": {json[message.sender]}, {said}'
                  + (', "replaced": true' if replaced else "") + _END)
        if len(self.kept) >= KEEP_MOST:  # a team's messages: thousands of lines a tick, megabytes
            self._write_kept()

    def put(self, record: dict[str, Any]) -> None:
        if self.kept:
            self._write_kept()
        self.sink.write(record)

    def flush(self) -> None:
        self.last_data = None  # the data's values may change from one tick to the next
        kept = self.kept
        if kept:  # _write_kept, without its call
            tick = self.clock.tick
            at = tick - self.first
            head = self.heads[at] if 0 <= at < len(self.heads) else self._head(tick)
            self.line(head)
            self.line(head.join(kept))
            kept.clear()
        self.sink_flush()

    def drain(self) -> None:
        if self.kept:
            self._write_kept()

    def _prefix(self, frame: Frame) -> Prefix:
        """The place `frame` runs in, found once a frame."""
        up = frame.up
        if up is None:
            prefix = self.tops.get(frame.agent) or self._top(frame.agent)
        elif isinstance(up, Frame):
            outer: Prefix = up.text or self._prefix(up)
            prefix = outer.below.get(up.state) or outer.inner(up.state, up.state.name)
        else:  # a region's: its owner's path, the owner's state and the region's name
            owner = up.owner
            outer = owner.text or self._prefix(owner)
            at = outer.below.get(owner.state) or outer.inner(owner.state, owner.state.name)
            prefix = at.below.get(up.spec) or at.inner(up.spec, up.spec.name)
        frame.text = prefix
        return prefix

    def _top(self, agent: Agent) -> Prefix:
        json = self.json
        top = self.tops[agent] = Prefix(f', "agent": {json[agent.name]}, "path": [{json[agent.top]}, ', json)
        return top

    def _deadlines(self, frame: Frame) -> str:
        """`, "deadline": …, "machine_deadline": …}\n` (those set); the last one made is kept."""
        shown = self.state_deadline, self.deadline = frame.state_deadline, frame.deadline
        if shown != self.shown:
            dt = self.clock.dt
            self.shown = shown
            self.shown_text = (
                "".join(
                    f', "{name}": {seconds_text(tick, dt)}'
                    for name, tick in zip(("deadline", "machine_deadline"), shown, strict=True)
                    if tick is not None
                )
                + _END
            )
        return self.shown_text

    def enter(self, frame: Frame, state: RState) -> None:
        if not frame.vars_shown:
            super().enter(frame, state)
            return
        prefix: Prefix = frame.text or self._prefix(frame)
        text = prefix.enters.get(state) or prefix.enter(state)
        if frame.deadline is None and frame.state_deadline is None:
            self.keep(text[1])
        elif frame.deadline == self.deadline and frame.state_deadline == self.state_deadline:
            self.keep(text[0] + self.shown_text)
        else:
            self.keep(text[0] + self._deadlines(frame))

    def arc(self, frame: Frame, state: RState, event: Event, target: RState | str | None) -> None:
        ends = (frame.text or self._prefix(frame)).arcs.get(state, _NONE).get(event.name)
        if ends is not None and ends[0] is target and frame.vars_shown:
            self.kept += ends[1]
        else:
            self._arc(frame, state, event, target)

    def _arc(self, frame: Frame, state: RState, event: Event, target: RState | str | None) -> None:
        """An arc not taken before from this place and state to this target, one whose record shows
        outputs of the callee (a barrier's: who arrived), or one taken after the vars changed."""
        if not frame.vars_shown or (state.traced and event.outputs):
            super().arc(frame, state, event, target)
            return
        ends = frame.text.arc(state, event.name, target)
        self.kept += ends[1]


_END = "}\n"
KEEP_MOST = 256  # lines kept before they go to the sink within a tick


def _copies(data: Any, other: Any) -> bool:
    """Whether two messages' data are shallow copies of one dict: the same keys in the same order,
    each holding the same object (so the same JSON)."""
    if data is other:
        return True
    if data.__class__ is not dict or other.__class__ is not dict or len(data) != len(other):
        return False
    return all(a is b and v is other[b] for (a, v), b in zip(data.items(), other, strict=True))
_NONE: dict[str, tuple[Any, tuple[str, str]]] = {}


def records_for(sink: TraceSink | None, clock: TraceClock) -> Records | None:
    if sink is None:
        return None
    if hasattr(sink, "write_line"):
        return TextRecords(sink, clock)  # type: ignore[arg-type]
    return Records(sink, clock)
