"""The server's diagnostics equal `hfsm-run --check`'s findings over every malformed machine file of
the test suite: the same lines, columns, spans (the caret's), codes, severities and messages. The
errors `--check` prints in the files a file calls are the related information of the diagnostics
at its `do:` (hfsm.lsp.callees): each of them, and nothing else."""

from __future__ import annotations

import asyncio
import io
import re
import sys
from collections.abc import AsyncIterator
from contextlib import redirect_stderr
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types as lsp
from pytest_lsp import ClientServerConfig, LanguageClient

from hfsm.cli import snippet
from hfsm.cli.run import main

TESTS = Path(__file__).resolve().parents[2]
LIBS = [TESTS / "spec" / "cases", TESTS / "errors" / "corpus" / "lib"]
MALFORMED = sorted(
    [*(TESTS / "spec" / "malformed").glob("*.yaml"), *(TESTS / "errors" / "corpus").glob("*.yaml")]
)
FINDING = re.compile(r"^(\S+):(\d+):(\d+): (error|warning)(?:\[(\w+)\])?: (.*)$")

Seen = tuple[int, int, int, str, str, str]  # line, first column, columns underlined, code, severity, message


@pytest_lsp.fixture(
    config=ClientServerConfig(server_command=[sys.executable, "-m", "hfsm.cli.lsp"]), scope="module"
)
async def client(lsp_client: LanguageClient) -> AsyncIterator[None]:
    options = {"world": "none", "lib": [str(p) for p in LIBS]}
    await lsp_client.initialize_session(
        lsp.InitializeParams(capabilities=lsp.ClientCapabilities(), initialization_options=options)
    )
    yield
    await lsp_client.shutdown_session()


def printed(path: Path, monkeypatch: pytest.MonkeyPatch) -> dict[str, list[Seen]]:
    """What `--check` prints, by file name, with each caret's column and width."""
    monkeypatch.chdir(path.parent)
    monkeypatch.setenv("NO_COLOR", "1")
    err = io.StringIO()
    libs = [arg for lib in LIBS for arg in ("--lib", str(lib))]
    with redirect_stderr(err):
        main([path.name, "--check", "--world", "none", *libs])
    lines = err.getvalue().splitlines()
    seen: dict[str, list[Seen]] = {}
    for i, line in enumerate(lines):
        found = FINDING.match(line)
        if found is None:
            continue
        carets = lines[i + 3].split("| ", 1)[1]
        start = len(carets) - len(carets.lstrip(" "))
        seen.setdefault(Path(found.group(1)).name, []).append(
            (int(found.group(2)), start, len(carets.strip()), found.group(5), found.group(4), found.group(6))
        )
    return seen


def related(diagnostics: list[lsp.Diagnostic]) -> list[tuple[str, int, int, str]]:
    """The callees' errors the diagnostics carry: file name, line, column (1-based), message."""
    return [
        (Path(r.location.uri).name, r.location.range.start.line + 1, r.location.range.start.character + 1, r.message)
        for d in diagnostics
        for r in d.related_information or []
    ]


def elsewhere(path: Path, check: dict[str, list[Seen]]) -> list[tuple[str, int, int, str]]:
    """The errors `--check` prints in other files than `path`, as `related` gives them."""
    return [
        (name, line, _column(path.parent / name, line, start), f"error[{code}]: {message}")
        for name, seen in check.items()
        if name != path.name
        for line, start, _, code, severity, message in seen
        if severity == "error"
    ]


def _column(path: Path, line: int, shown: int) -> int:
    """The 1-based column of the character the caret stands under (tabs widened)."""
    text = path.read_text(encoding="utf-8").splitlines()[line - 1] if path.is_file() else ""
    for i in range(len(text) + 1):
        if len(text[:i].replace("\t", snippet.TAB)) >= shown:
            return i + 1
    return shown + 1


def published(path: Path, diagnostics: list[lsp.Diagnostic]) -> list[Seen]:
    """The diagnostics in the same terms: columns as the terminal shows them (tabs widened)."""
    lines = path.read_text(encoding="utf-8").splitlines()
    seen = []
    for d in diagnostics:
        text = lines[d.range.start.line] if d.range.start.line < len(lines) else ""
        before = text[: d.range.start.character].replace("\t", snippet.TAB)
        under = text[d.range.start.character : d.range.end.character].replace("\t", snippet.TAB)
        severity = "error" if d.severity == lsp.DiagnosticSeverity.Error else "warning"
        seen.append(
            (d.range.start.line + 1, len(before), max(1, len(under)), str(d.code), severity, d.message)
        )
    return seen


@pytest.mark.asyncio(loop_scope="module")
async def test_the_server_reports_what_check_prints_for_every_malformed_file(
    client: LanguageClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert len(MALFORMED) >= 90
    differ, callers = [], 0
    for path in MALFORMED:
        uri = path.resolve().as_uri()
        client.diagnostics.pop(uri, None)
        item = lsp.TextDocumentItem(uri, "yaml", 1, path.read_text(encoding="utf-8"))
        client.text_document_did_open(lsp.DidOpenTextDocumentParams(item))
        while uri not in client.diagnostics:
            await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
        found = client.diagnostics[uri]
        server = sorted(published(path, [d for d in found if not d.related_information]))
        check = printed(path, monkeypatch)
        if server != sorted(check.get(path.name, [])):
            differ.append((path.name, server, check.get(path.name, [])))
        if set(related(found)) != set(elsewhere(path, check)):
            differ.append((path.name, related(found), elsewhere(path, check)))
        callers += any(d.related_information for d in found)
        client.text_document_did_close(lsp.DidCloseTextDocumentParams(lsp.TextDocumentIdentifier(uri)))
    assert differ == []
    assert callers >= 1  # the corpus has a file whose callees have errors


def _commented(text: str) -> str | None:
    """The text with a comment after its first state's key (an edit inside one state), if it has one."""
    lines = text.split("\n")
    if "states:" not in lines:
        return None
    for i in range(lines.index("states:") + 1, len(lines)):
        if lines[i].startswith("  ") and lines[i][2:3].isalpha() and lines[i].rstrip().endswith(":"):
            lines[i] = lines[i].rstrip() + "  # edited"
            return "\n".join(lines)
    return None


@pytest.mark.asyncio(loop_scope="module")
async def test_an_edit_inside_one_state_keeps_every_diagnostic(client: LanguageClient) -> None:
    """What the server reads again from the changed state alone (hfsm.lsp.reparse) gives the same
    diagnostics as the whole file read: a comment added to a state changes none of them."""
    edited = 0
    for path in MALFORMED:
        text = path.read_text(encoding="utf-8")
        changed = _commented(text)
        if changed is None:
            continue
        uri = path.resolve().as_uri()
        client.diagnostics.pop(uri, None)
        client.text_document_did_open(lsp.DidOpenTextDocumentParams(lsp.TextDocumentItem(uri, "yaml", 1, text)))
        while uri not in client.diagnostics:
            await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
        before = client.diagnostics.pop(uri)
        client.text_document_did_change(
            lsp.DidChangeTextDocumentParams(
                lsp.VersionedTextDocumentIdentifier(version=2, uri=uri),
                [lsp.TextDocumentContentChangeWholeDocument(changed)],
            )
        )
        while uri not in client.diagnostics:
            await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
        assert client.diagnostics[uri] == before, path.name
        edited += 1
        client.text_document_did_close(lsp.DidCloseTextDocumentParams(lsp.TextDocumentIdentifier(uri)))
    assert edited >= 50  # most of them read again from the changed state alone
