"""Breakpoints: a trace record that matches one pauses the run at the start of the next tick.

A breakpoint is `KIND:PATTERN`, optionally `@AGENT`: KIND is a kind of record (`enter`, `exit`,
`event`, `send`, `receive`, `held`, `error`, `timeout`, `failed`); PATTERN is matched (as a shell
pattern: `*`, `?`) against the state's path below the top machine (`grasp/reach`, `*/reach`) for
`enter`, `exit`, `held`, `error`, `timeout` and `failed`, against the event's name for `event`
(`done`, or `PATH>EVENT`: `grasp>failed`), and against the message's name for `send` and `receive`.

`cond:EXPR[@AGENT]` is a condition over `vars` and `in` instead (`runtime.condbreaks`): tried at the
end of every tick for each agent, it pauses the run when it turns true.
"""

from __future__ import annotations

import json
from collections.abc import Collection, Iterable
from dataclasses import dataclass, field
from fnmatch import fnmatchcase
from typing import Any

from hfsm.expr import ExprSyntaxError, Fn, Names, compile_expr
from hfsm.model import Machine
from hfsm.names import is_name
from hfsm.trace import Lines, TraceSink

KINDS = ("enter", "exit", "event", "send", "receive", "held", "error", "timeout", "failed", "cond")
COND = "cond:"


class BreakError(ValueError):
    """A breakpoint that cannot be set; `col` and `end` (1-based, in its text) for a condition's
    characters at fault, `code` the check's code (E314 a bad expression, E330 an input the world
    does not declare, E331 a name that cannot be read in a condition)."""

    def __init__(self, message: str, col: int = 1, end: int | None = None, code: str = "E314") -> None:
        super().__init__(message)
        self.col = col
        self.end = end if end is not None else col
        self.code = code


@dataclass(frozen=True)
class Breakpoint:
    kind: str
    pattern: str  # a condition's expression, as given
    agent: str | None = None
    test: Fn | None = field(default=None, compare=False, repr=False)  # a condition, compiled

    @property
    def text(self) -> str:
        return f"{self.kind}:{self.pattern}" + (f"@{self.agent}" if self.agent else "")

    def matches(self, record: dict[str, Any]) -> bool:
        if record.get("kind") != self.kind or self.kind == "cond":
            return False
        if self.agent is not None and record.get("agent") != self.agent:
            return False
        path = "/".join(str(p) for p in record.get("path", ())[1:])
        if self.kind in ("send", "receive"):
            return fnmatchcase(str(record.get("message")), self.pattern)
        if self.kind == "event":
            event = str(record.get("event"))
            return fnmatchcase(event, self.pattern) or fnmatchcase(f"{path}>{event}", self.pattern)
        return fnmatchcase(path, self.pattern)


def condition_names(machines: Iterable[Machine], inputs: Collection[str]) -> Names:
    """What a condition may read: the vars of every machine of the run, the world's inputs and
    `agent.id` (no params, no `state.*` nor `machine.time`: it belongs to no state)."""
    known = {name for machine in machines for name in machine.vars}
    return Names(params=(), vars=known, state=False, machine_time=False, inputs=inputs)


def parse(text: str, names: Names | None = None) -> Breakpoint:
    """`KIND:PATTERN[@AGENT]` (BreakError with the reason if it is not one). A condition's
    expression is compiled against `names` when given (else only split off: `compiled` does it)."""
    if text.startswith(COND):
        return _condition(text[len(COND):], names)
    kind, sep, rest = text.partition(":")
    pattern, at, agent = rest.rpartition("@") if "@" in rest else (rest, "", "")
    if not sep or kind not in KINDS or not pattern or (at and not agent):
        raise BreakError(f"{text!r}: write KIND:PATTERN[@AGENT], KIND one of {', '.join(KINDS)}")
    return Breakpoint(kind, pattern, agent or None)


def _condition(rest: str, names: Names | None) -> Breakpoint:
    """`EXPR` or `EXPR@AGENT` (an `@` followed by anything but a name belongs to the expression)."""
    expr, at, agent = rest.rpartition("@")
    if not at or not is_name(agent):
        expr, agent = rest, ""
    if not expr.strip():
        raise BreakError(f"'cond:{rest}': write cond:EXPR[@AGENT], EXPR an expression over vars and in")
    test = None
    if names is not None:
        try:
            test = compile_expr(expr, names)
        except ExprSyntaxError as exc:
            start = len(COND) + 1 + (exc.start or 0)
            end = len(COND) + 1 + (exc.end if exc.end is not None else len(expr))
            raise BreakError(exc.message, start, max(end, start), _code(exc.message)) from None
    return Breakpoint("cond", expr, agent or None, test)


def _code(message: str) -> str:
    if "unknown input" in message:
        return "E330"
    return "E331" if "cannot be read" in message else "E314"


def compiled(points: list[Breakpoint], names: Names) -> tuple[list[Breakpoint], list[BreakError]]:
    """The breakpoints with their conditions compiled, and the problems of those that do not compile."""
    done: list[Breakpoint] = []
    problems: list[BreakError] = []
    for point in points:
        try:
            done.append(parse(point.text, names) if point.kind == "cond" else point)
        except BreakError as exc:
            problems.append(exc)
    return done, problems


class Breaks:
    """A trace sink (in front of the run's own) that notes the first breakpoint a record matches."""

    def __init__(self, points: list[Breakpoint], sink: TraceSink | None) -> None:
        self.points = points
        self.sink = sink
        self.hit: str | None = None
        self.was: dict[tuple[str, str], bool] = {}  # a condition's value for an agent at the last tick

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


class LineBreaks(Breaks):
    """Breaks in front of a sink that takes lines (a trace file): the engine's lines go on as they
    are; they are read as records only while a breakpoint on records is set."""

    def __init__(self, points: list[Breakpoint], sink: Any) -> None:
        super().__init__(points, sink)
        self._lines = Lines()
        self._pass = sink.write_line

    def write_line(self, text: str) -> None:
        if any(p.kind != "cond" for p in self.points):
            for line in self._lines.feed(text):
                try:
                    self._match(json.loads(line))
                except ValueError:  # the end of a line begun before the breakpoint was set
                    continue
        self._pass(text)

    def _match(self, record: dict[str, Any]) -> None:
        for point in self.points:
            if self.hit is None and point.matches(record):
                self.hit = point.text
