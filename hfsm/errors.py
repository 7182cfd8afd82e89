"""Findings and the error classes: user errors carry findings with positions; bugs stay exceptions."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from enum import StrEnum


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"


@dataclass(frozen=True, order=True)
class Finding:
    """One problem in one file, at a 1-based line and column; `end`, when known, is the line and
    column just after the characters at fault (a span inside an expression, for a caret)."""

    file: str
    line: int
    col: int
    code: str
    message: str
    severity: Severity = field(default=Severity.ERROR, compare=False)
    end: tuple[int, int] | None = field(default=None, compare=False)

    def format(self) -> str:
        """One line, whatever text the message quotes (a line break is shown as `\\n`)."""
        label = f"{self.severity.value}[{self.code}]" if self.code else self.severity.value
        text = f"{self.file}:{self.line}:{self.col}: {label}: {self.message}"
        lines = text.splitlines()
        return text if len(lines) == 1 else "\\n".join(lines)

    def as_error(self) -> Finding:
        return replace(self, severity=Severity.ERROR)


class HfsmError(Exception):
    """Root of the errors hfsm raises on purpose."""


class UserError(HfsmError):
    """Bad input: a file, an argument. Printed without a traceback; exit 2."""

    def __init__(self, findings: Iterable[Finding]) -> None:
        self.findings = sorted(set(findings))
        super().__init__("\n".join(f.format() for f in self.findings))


class UsageError(HfsmError):
    """A bad command-line argument, not tied to a file position; exit 2."""
