"""The trace of a resumed run, checked against the old one up to T as it is written (`--resume`)."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from hfsm.runtime.core import FatalError
from hfsm.runtime.program import span_ticks

if TYPE_CHECKING:
    from hfsm.cli.resume import Resume


class PrefixCheck:
    """A trace sink over the new trace file: its lines up to T must be the old trace's, byte for byte;
    the first line after T is preceded by the `resume` record."""

    def __init__(self, file: Any, resume: Resume, edited: list[str], dt: float) -> None:
        self.file = file
        self.resume = resume
        self.edited = edited
        self.dt = dt
        self.tick = span_ticks(resume.at, dt)
        self.seen = 0
        self.last = 0.0  # the time of the last line checked
        self.checking = True
        self.buffer = ""
        self.failed: str | None = None

    def write(self, record: dict[str, Any]) -> None:
        self.write_line(json.dumps(record, ensure_ascii=False, allow_nan=False, default=str) + "\n")

    def write_line(self, text: str) -> None:
        if not self.checking:
            self.file.write_line(text)
            return
        self.buffer += text
        while "\n" in self.buffer:
            line, self.buffer = self.buffer.split("\n", 1)
            self._line(line)

    def _line(self, line: str) -> None:
        if self.checking:
            t = json.loads(line).get("t", 0.0)
            if self.seen == self.resume.prefix:  # the old trace up to T is a prefix of this one
                self.done(min(t, self.resume.at))
            elif span_ticks(t, self.dt) > self.tick or self.resume.lines[self.seen] != line:
                self.checking = False  # said once; what the run writes after is kept as it comes
                raise FatalError("", self._differs(line))
            else:
                self.seen += 1
                self.last = t
        self.file.write_line(line + "\n")

    def _differs(self, line: str) -> str:
        return (
            f"--resume: the run differs from {self.resume.path} at its line {self.seen + 2}: it wrote\n"
            f"  {line}\nwhere the trace has\n  {self.resume.lines[self.seen]}\n(a machine file changed "
            "what happened before T, or the trace was written by another version)"
        )

    def done(self, t: float) -> None:
        """Every old line up to T came: the `resume` record, and no more checks."""
        self.checking = False
        record = {
            "t": t,
            "agent": None,
            "path": [],
            "kind": "resume",
            "trace": str(self.resume.path),
            "at": self.resume.at,
            "edited": self.edited,
        }
        self.file.write_line(json.dumps(record, ensure_ascii=False) + "\n")

    def flush(self) -> None:
        self.file.flush()

    def close(self) -> None:
        self.file.close()
