"""Findings as LSP diagnostics: the same code, severity and message, over the span the terminal's
caret underlines (`hfsm.spans`)."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from pathlib import Path

from lsprotocol import types as lsp
from pygls.uris import from_fs_path

from hfsm.errors import Finding, Severity
from hfsm.spans import finding_span

SOURCE = "hfsm"


def finding_range(finding: Finding, lines: Sequence[str]) -> lsp.Range:
    """The 0-based range of what the finding points at, in the document's `lines`."""
    line = max(0, finding.line - 1)
    text = lines[line] if line < len(lines) else ""
    start, end = finding_span(text, finding)
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


def callee_diagnostic(
    at: Finding, name: str, errors: list[Finding], lines_of: Callable[[Path], Sequence[str]]
) -> lsp.Diagnostic:
    """The caller's diagnostic for a callee's errors (`hfsm.lsp.callees`), each error as related
    information at its own file's range; `lines_of`: a file's lines, as the editor holds them."""
    related = []
    for error in errors:
        path = Path(error.file).resolve()
        rng = finding_range(error, lines_of(path))
        message = f"error[{error.code}]: {error.message}" if error.code else error.message
        where = lsp.Location(from_fs_path(str(path)) or "", rng)
        related.append(lsp.DiagnosticRelatedInformation(where, message))
    return lsp.Diagnostic(
        range=finding_range(at, lines_of(Path(at.file).resolve())),
        message=at.message,
        severity=lsp.DiagnosticSeverity.Error,
        source=SOURCE,
        related_information=related,
        data={"callee": name},
    )


def of_file(findings: Iterable[Finding], path: Path) -> list[Finding]:
    """The findings about `path` (findings name files as printed: relative to the working folder)."""
    path = path.resolve()
    return [f for f in findings if Path(f.file).resolve() == path]
