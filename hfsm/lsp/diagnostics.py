"""Findings as LSP diagnostics: the same code, severity and message, over the span the terminal's
caret underlines (`hfsm.spans`)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path

from lsprotocol import types as lsp

from hfsm.errors import Finding, Severity
from hfsm.spans import span

SOURCE = "hfsm"


def finding_range(finding: Finding, lines: Sequence[str]) -> lsp.Range:
    """The 0-based range of what the finding points at, in the document's `lines`."""
    line = max(0, finding.line - 1)
    text = lines[line] if line < len(lines) else ""
    start, end = span(text, finding.col)
    return lsp.Range(lsp.Position(line, start - 1), lsp.Position(line, end - 1))


def to_diagnostic(finding: Finding, lines: Sequence[str]) -> lsp.Diagnostic:
    severity = lsp.DiagnosticSeverity.Error
    if finding.severity is Severity.WARNING:
        severity = lsp.DiagnosticSeverity.Warning
    return lsp.Diagnostic(
        range=finding_range(finding, lines),
        message=finding.message,
        severity=severity,
        code=finding.code or None,
        source=SOURCE,
    )


def of_file(findings: Iterable[Finding], path: Path) -> list[Finding]:
    """The findings about `path` (findings name files as printed: relative to the working folder)."""
    path = path.resolve()
    return [f for f in findings if Path(f.file).resolve() == path]
