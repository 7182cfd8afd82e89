"""Breakpoints: a trace record that matches one pauses the run at the start of the next tick.

A breakpoint is `KIND:PATTERN`, optionally `@AGENT`: KIND is a kind of record (`enter`, `exit`,
`event`, `send`, `receive`, `held`, `error`, `timeout`, `failed`); PATTERN is matched (as a shell
pattern: `*`, `?`) against the state's path below the top machine (`grasp/reach`, `*/reach`) for
`enter`, `exit`, `held`, `error`, `timeout` and `failed`, against the event's name for `event`
(`done`, or `PATH>EVENT`: `grasp>failed`), and against the message's name for `send` and `receive`.
"""

from __future__ import annotations

from dataclasses import dataclass
from fnmatch import fnmatchcase
from typing import Any

from hfsm.trace import TraceSink

KINDS = ("enter", "exit", "event", "send", "receive", "held", "error", "timeout", "failed")


@dataclass(frozen=True)
class Breakpoint:
    kind: str
    pattern: str
    agent: str | None = None

    @property
    def text(self) -> str:
        return f"{self.kind}:{self.pattern}" + (f"@{self.agent}" if self.agent else "")

    def matches(self, record: dict[str, Any]) -> bool:
        if record.get("kind") != self.kind or (self.agent is not None and record.get("agent") != self.agent):
            return False
        path = "/".join(str(p) for p in record.get("path", ())[1:])
        if self.kind in ("send", "receive"):
            return fnmatchcase(str(record.get("message")), self.pattern)
        if self.kind == "event":
            event = str(record.get("event"))
            return fnmatchcase(event, self.pattern) or fnmatchcase(f"{path}>{event}", self.pattern)
        return fnmatchcase(path, self.pattern)


def parse(text: str) -> Breakpoint:
    """`KIND:PATTERN[@AGENT]` (ValueError with the reason if it is not one)."""
    kind, sep, rest = text.partition(":")
    pattern, at, agent = rest.rpartition("@") if "@" in rest else (rest, "", "")
    if not sep or kind not in KINDS or not pattern or (at and not agent):
        raise ValueError(f"{text!r}: write KIND:PATTERN[@AGENT], KIND one of {', '.join(KINDS)}")
    return Breakpoint(kind, pattern, agent or None)


class Breaks:
    """A trace sink (in front of the run's own) that notes the first breakpoint a record matches."""

    def __init__(self, points: list[Breakpoint], sink: TraceSink | None) -> None:
        self.points = points
        self.sink = sink
        self.hit: str | None = None

    def write(self, record: dict[str, Any]) -> None:
        if self.hit is None:
            for point in self.points:
                if point.matches(record):
                    self.hit = point.text
                    break
        if self.sink is not None:
            self.sink.write(record)

    def flush(self) -> None:
        if self.sink is not None:
            self.sink.flush()

    def close(self) -> None:
        if self.sink is not None:
            self.sink.close()
