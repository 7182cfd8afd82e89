"""The server's diagnostics equal `hfsm-run --check`'s findings over every malformed machine file of
the test suite: the same lines, columns, spans (the caret's), codes, severities and messages."""

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
MALFORMED = sorted([*(TESTS / "spec" / "malformed").glob("*.yaml"), *(TESTS / "errors" / "corpus").glob("*.yaml")])
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


def printed(path: Path, monkeypatch: pytest.MonkeyPatch) -> list[Seen]:
    """What `--check` prints about `path` itself, with each caret's column and width."""
    monkeypatch.chdir(path.parent)
    monkeypatch.setenv("NO_COLOR", "1")
    err = io.StringIO()
    libs = [arg for lib in LIBS for arg in ("--lib", str(lib))]
    with redirect_stderr(err):
        main([path.name, "--check", "--world", "none", *libs])
    lines = err.getvalue().splitlines()
    seen = []
    for i, line in enumerate(lines):
        found = FINDING.match(line)
        if found is None or Path(found.group(1)).name != path.name:
            continue
        carets = lines[i + 3].split("| ", 1)[1]
        start = len(carets) - len(carets.lstrip(" "))
        seen.append((int(found.group(2)), start, len(carets.strip()), found.group(5), found.group(4), found.group(6)))
    return seen


def published(path: Path, diagnostics: list[lsp.Diagnostic]) -> list[Seen]:
    """The diagnostics in the same terms: columns as the terminal shows them (tabs widened)."""
    lines = path.read_text(encoding="utf-8").splitlines()
    seen = []
    for d in diagnostics:
        text = lines[d.range.start.line] if d.range.start.line < len(lines) else ""
        before = text[: d.range.start.character].replace("\t", snippet.TAB)
        under = text[d.range.start.character : d.range.end.character].replace("\t", snippet.TAB)
        severity = "error" if d.severity == lsp.DiagnosticSeverity.Error else "warning"
        seen.append((d.range.start.line + 1, len(before), max(1, len(under)), str(d.code), severity, d.message))
    return seen


@pytest.mark.asyncio(loop_scope="module")
async def test_the_server_reports_what_check_prints_for_every_malformed_file(
    client: LanguageClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert len(MALFORMED) >= 90
    differ = []
    for path in MALFORMED:
        uri = path.resolve().as_uri()
        client.diagnostics.pop(uri, None)
        item = lsp.TextDocumentItem(uri, "yaml", 1, path.read_text(encoding="utf-8"))
        client.text_document_did_open(lsp.DidOpenTextDocumentParams(item))
        while uri not in client.diagnostics:
            await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
        server = sorted(published(path, client.diagnostics[uri]))
        check = sorted(printed(path, monkeypatch))
        if server != check:
            differ.append((path.name, server, check))
        client.text_document_did_close(lsp.DidCloseTextDocumentParams(lsp.TextDocumentIdentifier(uri)))
    assert differ == []
