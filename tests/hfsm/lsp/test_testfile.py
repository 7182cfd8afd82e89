"""Test files (`*.test.yaml`) in the server: completion of the machine under test, its params, its
outcomes, the agents and the behaviours it calls (and their outcomes); hover on the machine, a
stand-in and an outcome; definition of the machine and of a stand-in's behaviour."""

from __future__ import annotations

import asyncio
import shutil
import sys
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types as lsp
from pytest_lsp import ClientServerConfig, LanguageClient

DATA = Path(__file__).resolve().parent / "data"

TEXT = """\
machine: caller
agents: [a, b]
tests:
  gets_it:
    params: {limit: 1}
    stand_ins:
      fetch: {after: 1, outcome: got, outputs: {thing: 1}}
    agent_params: {a: {limit: 2}}
    expect: {outcome: done, agents: {a: {outcome: done}}}
"""
LINES = TEXT.splitlines()


def uri(path: Path) -> str:
    return path.resolve().as_uri()


def _fields(line: int, character: int, path: Path) -> dict[str, object]:
    return {"text_document": lsp.TextDocumentIdentifier(uri(path)), "position": lsp.Position(line, character)}


async def open_file(client: LanguageClient, path: Path) -> None:
    item = lsp.TextDocumentItem(uri(path), "yaml", 1, path.read_text())
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(item))
    while uri(path) not in client.diagnostics:
        await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)


async def _labels(client: LanguageClient, path: Path, line: int, character: int) -> list[str]:
    result = await client.text_document_completion_async(lsp.CompletionParams(**_fields(line, character, path)))
    items = result.items if isinstance(result, lsp.CompletionList) else result or []
    return [item.label for item in items]


@pytest_lsp.fixture(config=ClientServerConfig(server_command=[sys.executable, "-m", "hfsm.cli.lsp"]))
async def client(lsp_client: LanguageClient) -> AsyncIterator[None]:
    await lsp_client.initialize_session(
        lsp.InitializeParams(capabilities=lsp.ClientCapabilities(), initialization_options={"world": "none"})
    )
    yield
    await lsp_client.shutdown_session()


@pytest.fixture
def test_file(tmp_path: Path) -> Path:
    for name in ("caller.yaml", "fetch.yaml"):
        shutil.copy(DATA / name, tmp_path / name)
    path = tmp_path / "caller.test.yaml"  # here: pytest would run it under tests/
    path.write_text(TEXT)
    return path


def _after(line: int, text: str) -> tuple[int, int]:
    """The position just after `text` on `line`."""
    return line, LINES[line].index(text) + len(text)


@pytest.mark.asyncio
async def test_completion_in_a_test_file_offers_what_fits(client: LanguageClient, test_file: Path) -> None:
    await open_file(client, test_file)
    machines = await _labels(client, test_file, *_after(0, "machine: "))
    assert {"caller", "fetch"} <= set(machines) and "wait" not in machines
    assert await _labels(client, test_file, *_after(4, "params: {")) == ["limit"]
    assert await _labels(client, test_file, 6, 6) == ["fetch"]  # a key of stand_ins: what it calls
    assert await _labels(client, test_file, *_after(6, "outcome: ")) == ["got", "lost"]
    assert await _labels(client, test_file, *_after(6, "outputs: {")) == ["thing"]
    assert await _labels(client, test_file, *_after(8, "{outcome: ")) == ["done", "failed"]
    assert await _labels(client, test_file, *_after(8, "agents: {")) == ["a", "b"]
    assert await _labels(client, test_file, *_after(8, "agents: {a: {outcome: ")) == ["done", "failed"]
    assert await _labels(client, test_file, *_after(7, "agent_params: {")) == ["a", "b"]
    assert await _labels(client, test_file, *_after(7, "agent_params: {a: {")) == ["limit"]


async def _hover(client: LanguageClient, path: Path, line: int, character: int) -> str:
    found = await client.text_document_hover_async(lsp.HoverParams(**_fields(line, character, path)))
    return str(found.contents) if found is not None else ""


@pytest.mark.asyncio
async def test_hover_and_definition_in_a_test_file(client: LanguageClient, test_file: Path) -> None:
    await open_file(client, test_file)
    assert "**caller** (machine)" in await _hover(client, test_file, 0, 11)
    assert "**fetch** (machine)" in await _hover(client, test_file, 6, 7)
    got = await _hover(client, test_file, *_after(6, "outcome: g"))
    assert "outcome **got** of `fetch`" in got
    done = await _hover(client, test_file, *_after(8, "{outcome: d"))
    assert "outcome **done** of `caller`" in done
    assert "param **limit** of `caller`: float" in await _hover(client, test_file, *_after(4, "{li"))
    machine = await client.text_document_definition_async(lsp.DefinitionParams(**_fields(0, 11, test_file)))
    assert isinstance(machine, lsp.Location) and machine.uri == uri(test_file.parent / "caller.yaml")
    stand_in = await client.text_document_definition_async(lsp.DefinitionParams(**_fields(6, 7, test_file)))
    assert isinstance(stand_in, lsp.Location) and stand_in.uri == uri(test_file.parent / "fetch.yaml")
