"""Columns in the client's units: UTF-16 code units unless UTF-8 (or UTF-32) was agreed at
initialization. A line with `é`, `中` and an emoji outside the BMP before an error: the range covers
the misspelt target in either encoding, hover finds the callee from a position in those units, and
the terminal's `FILE:LINE:COL` counts characters."""

from __future__ import annotations

import asyncio
import io
import sys
from collections.abc import AsyncIterator
from contextlib import redirect_stderr
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types as lsp
from pytest_lsp import ClientServerConfig, LanguageClient

from hfsm.cli.run import main

TEXT = """\
outcomes: [done]
states:
  go: {doc: "é中😀", do: wait, with: {seconds: 1}, on: {done: dnoe}}
"""
LINE = TEXT.splitlines()[2]
CONFIG = ClientServerConfig(server_command=[sys.executable, "-m", "hfsm.cli.lsp"])


async def _start(client: LanguageClient, encodings: list[lsp.PositionEncodingKind] | None) -> None:
    general = lsp.GeneralClientCapabilities(position_encodings=encodings) if encodings else None
    await client.initialize_session(
        lsp.InitializeParams(
            capabilities=lsp.ClientCapabilities(general=general), initialization_options={"world": "none"}
        )
    )


@pytest_lsp.fixture(config=CONFIG)
async def utf16(lsp_client: LanguageClient) -> AsyncIterator[LanguageClient]:
    await _start(lsp_client, None)
    yield lsp_client
    await lsp_client.shutdown_session()


@pytest_lsp.fixture(config=CONFIG)
async def utf8(lsp_client: LanguageClient) -> AsyncIterator[LanguageClient]:
    await _start(lsp_client, [lsp.PositionEncodingKind.Utf8])
    yield lsp_client
    await lsp_client.shutdown_session()


async def _diagnostics(client: LanguageClient, path: Path) -> list[lsp.Diagnostic]:
    uri = path.resolve().as_uri()
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(lsp.TextDocumentItem(uri, "yaml", 1, TEXT)))
    while uri not in client.diagnostics:
        await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
    return client.diagnostics[uri]


def _units(text: str, encoding: str) -> int:
    return len(text.encode(encoding)) // (2 if encoding == "utf-16-le" else 1)


@pytest.mark.asyncio
async def test_utf16_by_default_a_range_after_wide_characters_covers_the_misspelt_target(
    utf16: LanguageClient, tmp_path: Path
) -> None:
    await _wide_line(utf16, "utf-16-le", tmp_path)


@pytest.mark.asyncio
async def test_utf8_when_the_client_offers_it(utf8: LanguageClient, tmp_path: Path) -> None:
    await _wide_line(utf8, "utf-8", tmp_path)


async def _wide_line(client: LanguageClient, encoding: str, tmp_path: Path) -> None:
    path = tmp_path / "wide.yaml"
    path.write_text(TEXT, encoding="utf-8")
    (found,) = [d for d in await _diagnostics(client, path) if d.code == "E301"]
    start = LINE.index("dnoe")
    assert (found.range.start.character, found.range.end.character) == (
        _units(LINE[:start], encoding),
        _units(LINE[: start + 4], encoding),
    )
    assert found.range.start.character != start  # the encodings differ from characters on this line
    encoded = LINE.encode(encoding)
    width = 2 if encoding == "utf-16-le" else 1
    covered = encoded[found.range.start.character * width : found.range.end.character * width]
    assert covered.decode(encoding) == "dnoe"
    on_wait = lsp.Position(2, _units(LINE[: LINE.index("wait") + 1], encoding))
    hover = await client.text_document_hover_async(
        lsp.HoverParams(lsp.TextDocumentIdentifier(path.resolve().as_uri()), on_wait)
    )
    assert hover is not None and "**wait** (builtin)" in str(hover.contents)


def test_the_terminal_counts_characters(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "wide.yaml"
    path.write_text(TEXT, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("NO_COLOR", "1")
    err = io.StringIO()
    with redirect_stderr(err):
        assert main(["wide.yaml", "--check", "--world", "none"]) == 2
    assert f"wide.yaml:3:{LINE.index('dnoe') + 1}: error[E301]" in err.getvalue()
