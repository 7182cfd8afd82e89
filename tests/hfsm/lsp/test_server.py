"""`hfsm-lsp` end to end (pytest-lsp): the server runs as editors start it, over stdio."""

from __future__ import annotations

import asyncio
import sys
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types as lsp
from pytest_lsp import ClientServerConfig, LanguageClient

DATA = Path(__file__).resolve().parent / "data"


@pytest_lsp.fixture(
    config=ClientServerConfig(server_command=[sys.executable, "-m", "hfsm.cli.lsp"]), scope="module"
)
async def client(lsp_client: LanguageClient) -> AsyncIterator[None]:
    options = {"world": "none"}
    await lsp_client.initialize_session(
        lsp.InitializeParams(capabilities=lsp.ClientCapabilities(), initialization_options=options)
    )
    yield
    await lsp_client.shutdown_session()


def uri(path: Path) -> str:
    return path.resolve().as_uri()


async def open_file(client: LanguageClient, path: Path, text: str | None = None) -> list[lsp.Diagnostic]:
    """Open the file (its text on disk, or `text`) and return the diagnostics published for it."""
    client.diagnostics.pop(uri(path), None)
    item = lsp.TextDocumentItem(uri(path), "yaml", 1, path.read_text() if text is None else text)
    client.text_document_did_open(lsp.DidOpenTextDocumentParams(item))
    return await diagnostics_of(client, path)


async def diagnostics_of(client: LanguageClient, path: Path) -> list[lsp.Diagnostic]:
    while uri(path) not in client.diagnostics:
        await asyncio.wait_for(client.wait_for_notification(lsp.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
    return client.diagnostics[uri(path)]


def change(client: LanguageClient, path: Path, text: str, version: int) -> None:
    client.diagnostics.pop(uri(path), None)
    client.text_document_did_change(
        lsp.DidChangeTextDocumentParams(
            lsp.VersionedTextDocumentIdentifier(version=version, uri=uri(path)),
            [lsp.TextDocumentContentChangeWholeDocument(text)],
        )
    )


def at(line: int, character: int, path: Path) -> lsp.TextDocumentPositionParams:
    return lsp.TextDocumentPositionParams(
        lsp.TextDocumentIdentifier(uri(path)), lsp.Position(line, character)
    )


def brief(diagnostics: list[lsp.Diagnostic]) -> list[tuple[int, int, int, str | int | None, str]]:
    return [
        (d.range.start.line, d.range.start.character, d.range.end.character, d.code, str(d.severity))
        for d in diagnostics
    ]


@pytest.mark.asyncio(loop_scope="module")
async def test_errors_are_published_on_open_with_their_spans_and_all_at_once(client: LanguageClient) -> None:
    found = await open_file(client, DATA / "broken.yaml")
    assert brief(found) == [
        (3, 8, 12, "E300", "DiagnosticSeverity.Error"),
        (4, 4, 11, "E200", "DiagnosticSeverity.Error"),
        (5, 15, 20, "E301", "DiagnosticSeverity.Error"),
    ]
    assert found[0].message == "unknown behaviour 'wiat'; did you mean 'wait'?"
    assert {d.source for d in found} == {"hfsm"}


@pytest.mark.asyncio(loop_scope="module")
async def test_warnings_are_warnings_and_a_fix_clears_the_errors(client: LanguageClient) -> None:
    path = DATA / "broken.yaml"
    await open_file(client, path)
    fixed = (
        path.read_text().replace("wiat", "wait").replace("    timeout: 5\n", "").replace("fnish", "finish")
    )
    change(client, path, fixed, 2)
    found = await diagnostics_of(client, path)
    assert [d.code for d in found] == []
    caller = await open_file(client, DATA / "caller.yaml")
    assert [(d.code, d.severity) for d in caller] == [("W402", lsp.DiagnosticSeverity.Warning)]


@pytest.mark.asyncio(loop_scope="module")
async def test_a_change_to_a_callee_checks_its_open_callers_again(client: LanguageClient) -> None:
    caller, callee = DATA / "caller.yaml", DATA / "fetch.yaml"
    await open_file(client, caller)
    await open_file(client, callee)
    client.diagnostics.pop(uri(caller), None)
    change(client, callee, callee.read_text().replace("[got, lost]", "[got, lost, broke]"), 2)
    found = await diagnostics_of(client, caller)
    assert [(d.code, d.range.start.line, d.message) for d in found if d.code != "W402"] == [
        ("E308", 7, "outcome 'broke' of 'fetch' is not mapped in 'on'")
    ]


@pytest.mark.asyncio(loop_scope="module")
async def test_hover_shows_a_callee_a_state_and_a_param(client: LanguageClient) -> None:
    path = DATA / "caller.yaml"
    await open_file(client, path)
    callee = await client.text_document_hover_async(lsp.HoverParams(**_fields(at(7, 9, path))))
    assert callee is not None and isinstance(callee.contents, lsp.MarkupContent)
    assert "**fetch** (machine)" in callee.contents.value and "`tries`: int = 1" in callee.contents.value
    assert "outcomes: `got`, `lost`" in callee.contents.value and "outputs: `thing`" in callee.contents.value
    target = await client.text_document_hover_async(lsp.HoverParams(**_fields(at(9, 16, path))))
    assert target is not None and "state **rest**: calls `wait`" in str(target.contents)
    param = await client.text_document_hover_async(lsp.HoverParams(**_fields(at(12, 32, path))))
    assert param is not None and "**params.limit**: float = 2.0" in str(param.contents)


def _fields(params: lsp.TextDocumentPositionParams) -> dict[str, object]:
    return {"text_document": params.text_document, "position": params.position}


async def _labels(client: LanguageClient, path: Path, line: int, character: int) -> list[str]:
    result = await client.text_document_completion_async(
        lsp.CompletionParams(**_fields(at(line, character, path)))
    )
    items = result.items if isinstance(result, lsp.CompletionList) else result or []
    return [item.label for item in items]


@pytest.mark.asyncio(loop_scope="module")
async def test_completion_offers_what_fits_where_the_cursor_is(client: LanguageClient) -> None:
    path = DATA / "caller.yaml"
    text = path.read_text()
    await open_file(client, path)
    lines = text.splitlines()
    behaviours = await _labels(client, path, 7, len(lines[7]))
    assert {"fetch", "wait", "log", "barrier"} <= set(behaviours)
    params = await _labels(client, path, 8, len("    with: {"))
    assert params == ["tries"]
    events = await _labels(client, path, 9, len("    on: {"))
    assert events[:2] == ["got", "lost"] and "error" in events
    targets = await _labels(client, path, 9, len("    on: {got: "))
    assert targets == ["get", "rest", "check", "done", "failed"]
    names = await _labels(client, path, 12, len('    with: {seconds: "${params.'))
    assert names == ["limit"]
    change(client, path, text.replace("vars.count > 1", "vars."), 2)
    await diagnostics_of(client, path)
    assert await _labels(client, path, 17, len("      - if: vars.")) == ["count"]


@pytest.mark.asyncio(loop_scope="module")
async def test_completion_offers_a_params_values_when_it_takes_a_fixed_set(client: LanguageClient) -> None:
    path = DATA / "sender.yaml"
    await open_file(client, path)
    assert "keep" in await _labels(client, path, 5, len("    with: {"))
    assert await _labels(client, path, 5, len("    with: {message: hello, keep: ")) == ["all", "last"]
    assert await _labels(client, path, 5, len("    with: {message: ")) == []


@pytest.mark.asyncio(loop_scope="module")
async def test_untraced_completes_and_renames_with_the_machines_vars(client: LanguageClient) -> None:
    path = DATA / "quiet.yaml"
    await open_file(client, path)
    assert await _labels(client, path, 2, len("untraced: [")) == ["hold", "n"]
    refs = await client.text_document_references_async(
        lsp.ReferenceParams(context=lsp.ReferenceContext(include_declaration=True), **_fields(at(2, 12, path)))
    )
    assert sorted((r.range.start.line, r.range.start.character) for r in refs or []) == [(1, 7), (2, 11)]


@pytest.mark.asyncio(loop_scope="module")
async def test_definition_goes_to_a_state_a_machine_and_a_primitive(client: LanguageClient) -> None:
    path = DATA / "caller.yaml"
    await open_file(client, path)
    state = await client.text_document_definition_async(lsp.DefinitionParams(**_fields(at(9, 16, path))))
    assert isinstance(state, lsp.Location) and state.uri == uri(path) and state.range.start.line == 10
    machine = await client.text_document_definition_async(lsp.DefinitionParams(**_fields(at(7, 9, path))))
    assert isinstance(machine, lsp.Location) and machine.uri == uri(DATA / "fetch.yaml")
    var = await client.text_document_definition_async(lsp.DefinitionParams(**_fields(at(17, 17, path))))
    assert isinstance(var, lsp.Location) and var.range.start.line == 3


@pytest.mark.asyncio(loop_scope="module")
async def test_references_and_rename_of_a_state_within_the_file(client: LanguageClient) -> None:
    path = DATA / "caller.yaml"
    await open_file(client, path)
    refs = await client.text_document_references_async(
        lsp.ReferenceParams(context=lsp.ReferenceContext(include_declaration=True), **_fields(at(6, 3, path)))
    )
    assert sorted((r.range.start.line, r.range.start.character) for r in refs or []) == [(6, 2), (19, 14)]
    edit = await client.text_document_rename_async(
        lsp.RenameParams(new_name="fetch_it", **_fields(at(6, 3, path)))
    )
    assert edit is not None and edit.changes is not None
    assert {e.new_text for e in edit.changes[uri(path)]} == {"fetch_it"} and len(edit.changes[uri(path)]) == 2


@pytest.mark.asyncio(loop_scope="module")
async def test_renaming_an_outcome_renames_it_in_its_callers(client: LanguageClient) -> None:
    caller, callee = DATA / "caller.yaml", DATA / "fetch.yaml"
    await open_file(client, caller)
    await open_file(client, callee)
    edit = await client.text_document_rename_async(
        lsp.RenameParams(new_name="fetched", **_fields(at(4, 12, callee)))
    )
    assert edit is not None and edit.changes is not None
    assert sorted((e.range.start.line, e.range.start.character) for e in edit.changes[uri(callee)]) == [
        (4, 11),
        (9, 15),
    ]
    assert [(e.range.start.line, e.range.start.character) for e in edit.changes[uri(caller)]] == [(9, 9)]


@pytest.mark.asyncio(loop_scope="module")
async def test_document_symbols_list_states_params_vars_and_outcomes(client: LanguageClient) -> None:
    path = DATA / "caller.yaml"
    await open_file(client, path)
    found = await client.text_document_document_symbol_async(
        lsp.DocumentSymbolParams(lsp.TextDocumentIdentifier(uri(path)))
    )
    names = [(s.name, s.kind) for s in found or [] if isinstance(s, lsp.DocumentSymbol)]
    assert names == [
        ("limit", lsp.SymbolKind.Property),
        ("count", lsp.SymbolKind.Variable),
        ("done", lsp.SymbolKind.EnumMember),
        ("failed", lsp.SymbolKind.EnumMember),
        ("get", lsp.SymbolKind.Class),
        ("rest", lsp.SymbolKind.Class),
        ("check", lsp.SymbolKind.Class),
    ]


@pytest.mark.asyncio(loop_scope="module")
async def test_every_suggestion_is_a_quick_fix(client: LanguageClient) -> None:
    path = DATA / "broken.yaml"
    found = await open_file(client, path)
    actions = await client.text_document_code_action_async(
        lsp.CodeActionParams(
            lsp.TextDocumentIdentifier(uri(path)),
            lsp.Range(lsp.Position(0, 0), lsp.Position(9, 0)),
            lsp.CodeActionContext(diagnostics=found),
        )
    )
    edits = [
        (e.range.start.line, e.range.start.character, e.new_text)
        for a in actions or []
        if isinstance(a, lsp.CodeAction) and a.edit and a.edit.changes
        for e in a.edit.changes[uri(path)]
    ]
    assert edits == [(3, 8, "wait"), (4, 4, "timer"), (5, 15, "finish")]


@pytest.mark.asyncio(loop_scope="module")
async def test_a_test_file_gets_hfsm_tests_findings(client: LanguageClient, tmp_path: Path) -> None:
    (tmp_path / "fetch.yaml").write_text((DATA / "fetch.yaml").read_text())
    path = tmp_path / "fetch.test.yaml"  # written here: pytest would collect a bad one under tests/
    path.write_text(
        "machine: fetch\ntests:\n  gets_it:\n    params: {trys: 2}\n    expect: {outcome: gott}\n"
    )
    found = await open_file(client, path)
    assert [(d.code, d.range.start.line, d.range.start.character, d.message) for d in found] == [
        ("T303", 3, 13, "'fetch' has no param 'trys'; did you mean 'tries'?"),
        ("T321", 4, 22, "'fetch' has no outcome 'gott'; did you mean 'got'?"),
    ]


@pytest.mark.asyncio(loop_scope="module")
async def test_a_callees_errors_are_shown_at_the_callers_do_with_each_as_related_information(
    client: LanguageClient, tmp_path: Path
) -> None:
    (tmp_path / "fetch.yaml").write_text(
        "outcomes: [got, lost]\nstates:\n  try:\n    do: wiat\n    on: {done: got, error: lost}\n"
    )
    broken = "outcomes: [done]\nstates: {a: {do: wait, on: {done: done}\n"
    (tmp_path / "broke.yaml").write_text(broken)
    caller = tmp_path / "caller.yaml"
    caller.write_text(
        "outcomes: [done, failed]\nstates:\n  get:\n    do: fetch\n    on: {got: next, lost: failed}\n"
        "  next: {do: broke, on: {done: done}}\n"
    )
    found = await open_file(client, caller)
    assert [(d.range.start.line, d.range.start.character, d.range.end.character, d.code) for d in found] == [
        (3, 8, 13, None),
        (5, 13, 18, None),
    ]
    assert found[0].message.startswith("'fetch' has 1 error: first at ")
    assert found[0].message.endswith("fetch.yaml:4:9: unknown behaviour 'wiat'; did you mean 'wait'?")
    related = found[0].related_information or []
    assert [(r.location.uri, r.location.range.start.line, r.location.range.start.character) for r in related] == [
        (uri(tmp_path / "fetch.yaml"), 3, 8)
    ]
    assert related[0].message == "error[E300]: unknown behaviour 'wiat'; did you mean 'wait'?"
    assert found[1].message.startswith("'broke' has 1 error: first at ") and "never closed" in found[1].message
    actions = await client.text_document_code_action_async(
        lsp.CodeActionParams(
            lsp.TextDocumentIdentifier(uri(caller)),
            lsp.Range(lsp.Position(0, 0), lsp.Position(6, 0)),
            lsp.CodeActionContext(diagnostics=found),
        )
    )
    assert not actions  # the fixes are the callee's, in its own file
    callee = tmp_path / "broke.yaml"
    await open_file(client, callee)
    client.diagnostics.pop(uri(caller), None)
    change(client, callee, broken.replace("done}\n", "done}}}\n"), 2)
    again = await diagnostics_of(client, caller)
    assert [d.range.start.line for d in again] == [3]
