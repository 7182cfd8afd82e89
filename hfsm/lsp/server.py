"""The wiring: pygls features over stdio, each handing its work to the module of its job.

Diagnostics are published on open and on every change, for the document and for the open
documents that call it (their checks read it). Initialization options: `{"lib": [DIR, ...],
"world": NAME}`, as `hfsm-run --check`'s `--lib` and `--world`.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any

from lsprotocol import types as lsp
from pygls.lsp.server import LanguageServer
from pygls.uris import from_fs_path, to_fs_path

from hfsm.library import MachineFile
from hfsm.lsp import actions, completion, diagnostics, hover, navigation, testfile
from hfsm.lsp.analysis import Analysis, Settings, Workspace, is_test_file
from hfsm.lsp.callees import callee_errors
from hfsm.lsp.units import Units
from hfsm.yamlio import Document

_OURS = re.compile(r"\b(states|outcomes|tests)\s*:")


def _version() -> str:
    try:
        return version("hfsm")
    except PackageNotFoundError:
        return "0"


class HfsmServer(LanguageServer):
    def __init__(self, workspace: Workspace | None = None) -> None:
        super().__init__("hfsm-lsp", _version())
        self.state = workspace or Workspace()

    def lines(self, path: Path) -> Sequence[str]:
        text = self.state.texts.get(path.resolve())
        if text is None:
            try:
                text = path.read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError):
                text = ""
        return text.splitlines()

    def changed(self, uri: str, text: str) -> None:
        path = _path(uri)
        if not (is_test_file(path) or _OURS.search(text)):
            self.text_document_publish_diagnostics(lsp.PublishDiagnosticsParams(uri=uri, diagnostics=[]))
            return  # another YAML file (a CI file, a scenario): not ours to check
        for again in self.state.set_text(path, text):
            self.publish(again, self.state.analyse(again))

    @property
    def units(self) -> Units:
        return Units(self.workspace.position_codec)

    def position(self, uri: str, pos: lsp.Position) -> lsp.Position:
        """A position the client sent, in characters of the document."""
        return self.units.position_in(self.lines(_path(uri)), pos)

    def range_out(self, uri: str, rng: lsp.Range) -> lsp.Range:
        """A range in characters of the file at `uri`, in the client's units."""
        return self.units.range_out(self.lines(_path(uri)), rng)

    def publish(self, path: Path, analysis: Analysis) -> None:
        lines = self.lines(path)
        found = [diagnostics.to_diagnostic(f, lines) for f in diagnostics.of_file(analysis.findings, path)]
        for c in callee_errors(analysis):
            found.append(diagnostics.callee_diagnostic(c.at, c.name, c.errors, self.lines))
        units = self.units
        for diagnostic in found:
            diagnostic.range = units.range_out(lines, diagnostic.range)
            for related in diagnostic.related_information or ():
                related.location.range = self.range_out(related.location.uri, related.location.range)
        self.text_document_publish_diagnostics(
            lsp.PublishDiagnosticsParams(uri=from_fs_path(str(path)) or "", diagnostics=found)
        )

    def test_context(self, uri: str) -> tuple[Analysis, Document, Sequence[str]] | None:
        """A test file's latest check, its latest well-read text, and its lines now."""
        path = _path(uri)
        analysis = self.state.analyses.get(path)
        doc = self.state.last_tests.get(path)
        if not is_test_file(path) or analysis is None or doc is None:
            return None
        return analysis, doc, self.lines(path)

    def context(self, uri: str) -> tuple[Analysis, MachineFile, Sequence[str]] | None:
        """The document's latest check, its latest well-read machine, and its lines now."""
        path = _path(uri)
        analysis = self.state.analyses.get(path)
        machine = self.state.last_good.get(path)
        if analysis is None or machine is None:
            return None
        return analysis, machine, self.lines(path)


def _path(uri: str) -> Path:
    return Path(to_fs_path(uri) or uri).resolve()


def build(workspace: Workspace | None = None) -> HfsmServer:  # noqa: C901 (one small handler per feature)
    server = HfsmServer(workspace)

    @server.feature(lsp.INITIALIZE)
    def initialize(ls: HfsmServer, params: lsp.InitializeParams) -> None:
        options: Any = params.initialization_options or {}
        if isinstance(options, dict):
            libs = [Path(p) for p in options.get("lib", []) if isinstance(p, str)]
            world = options.get("world") if isinstance(options.get("world"), str) else None
            ls.state.settings = Settings(libs, world)

    @server.feature(lsp.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: HfsmServer, params: lsp.DidOpenTextDocumentParams) -> None:
        ls.changed(params.text_document.uri, params.text_document.text)

    @server.feature(lsp.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: HfsmServer, params: lsp.DidChangeTextDocumentParams) -> None:
        uri = params.text_document.uri
        ls.changed(uri, ls.workspace.get_text_document(uri).source)

    @server.feature(lsp.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: HfsmServer, params: lsp.DidCloseTextDocumentParams) -> None:
        ls.state.close(_path(params.text_document.uri))

    @server.feature(lsp.TEXT_DOCUMENT_HOVER)
    def on_hover(ls: HfsmServer, params: lsp.HoverParams) -> lsp.Hover | None:
        uri = params.text_document.uri
        tests = ls.test_context(uri)
        if tests is not None:
            return testfile.hover(*tests, ls.position(uri, params.position))
        found = ls.context(uri)
        return hover.hover(*found, ls.position(uri, params.position)) if found else None

    @server.feature(lsp.TEXT_DOCUMENT_COMPLETION, lsp.CompletionOptions(trigger_characters=[".", " ", "{"]))
    def on_completion(ls: HfsmServer, params: lsp.CompletionParams) -> lsp.CompletionList:
        path = _path(params.text_document.uri)
        analysis = ls.state.analyses.get(path)
        if analysis is None:
            return lsp.CompletionList(is_incomplete=False, items=[])
        machine = ls.state.last_good.get(path)
        lines = ls.lines(path)
        pos = ls.units.position_in(lines, params.position)
        if is_test_file(path):
            items = testfile.complete(analysis, ls.state.last_tests.get(path), lines, pos)
        else:
            items = completion.complete(analysis, machine, lines, pos)
        return lsp.CompletionList(is_incomplete=False, items=items)

    @server.feature(lsp.TEXT_DOCUMENT_DEFINITION)
    def on_definition(ls: HfsmServer, params: lsp.DefinitionParams) -> lsp.Location | None:
        uri = params.text_document.uri
        found = _definition(ls, uri, ls.position(uri, params.position))
        return lsp.Location(found.uri, ls.range_out(found.uri, found.range)) if found else None

    @server.feature(lsp.TEXT_DOCUMENT_REFERENCES)
    def on_references(ls: HfsmServer, params: lsp.ReferenceParams) -> list[lsp.Location]:
        uri = params.text_document.uri
        places = _places(ls, uri, ls.position(uri, params.position))
        return [lsp.Location(u, ls.range_out(u, r)) for u, rs in places.items() for r in rs]

    @server.feature(lsp.TEXT_DOCUMENT_RENAME)
    def on_rename(ls: HfsmServer, params: lsp.RenameParams) -> lsp.WorkspaceEdit | None:
        uri = params.text_document.uri
        places = _places(ls, uri, ls.position(uri, params.position))
        if not places:
            return None
        edit = params.new_name
        changes = {u: [lsp.TextEdit(ls.range_out(u, r), edit) for r in rs] for u, rs in places.items()}
        return lsp.WorkspaceEdit(changes=changes)

    @server.feature(lsp.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    def on_symbols(ls: HfsmServer, params: lsp.DocumentSymbolParams) -> list[lsp.DocumentSymbol]:
        found = ls.context(params.text_document.uri)
        return ls.units.symbols_out(found[2], navigation.symbols(found[1], found[2])) if found else []

    @server.feature(
        lsp.TEXT_DOCUMENT_CODE_ACTION, lsp.CodeActionOptions(code_action_kinds=[lsp.CodeActionKind.QuickFix])
    )
    def on_code_action(ls: HfsmServer, params: lsp.CodeActionParams) -> list[lsp.CodeAction]:
        uri = params.text_document.uri
        lines = ls.lines(_path(uri))
        units = ls.units
        return actions.quick_fixes(uri, lines, params.context.diagnostics, lambda r: units.range_in(lines, r))

    return server


def _definition(ls: HfsmServer, uri: str, pos: lsp.Position) -> lsp.Location | None:
    tests = ls.test_context(uri)
    if tests is not None:
        called = testfile.definition_name(tests[1], tests[2], pos)
        file = _behaviour_file(tests[0], called) if called else None
        if file is None:
            return None
        begin = lsp.Position(file[1], 0)
        return lsp.Location(from_fs_path(str(file[0])) or "", lsp.Range(begin, begin))
    found = ls.context(uri)
    if found is None:
        return None
    analysis, machine, lines = found
    name = navigation.name_at(machine, lines, pos)
    if name is None:
        return None
    if name.kind != "behaviour":
        rng = navigation.definition(machine, lines, name)
        return lsp.Location(uri, rng) if rng else None
    target = _behaviour_file(analysis, name.text)
    if target is None:
        return None
    start = lsp.Position(target[1], 0)
    return lsp.Location(from_fs_path(str(target[0])) or "", lsp.Range(start, start))


def _behaviour_file(analysis: Analysis, name: str) -> tuple[Path, int] | None:
    """A machine's file, a primitive's Python function, a built-in's declaration."""
    primitive = analysis.registry.get(name)
    if primitive is not None:
        target = primitive.target
        if isinstance(target, str):
            return navigation.python_definition(target)
        code = getattr(target, "__code__", None)
        return (Path(code.co_filename), code.co_firstlineno - 1) if code else None
    if analysis.library is not None:
        path = analysis.library.find(name)
        if path is not None:
            return path.resolve(), 0
    if name in analysis.specs and analysis.specs[name].kind == "builtin":
        from hfsm import builtins

        path = Path(builtins.__file__)
        lines = path.read_text(encoding="utf-8").splitlines()
        return path, next((n for n, t in enumerate(lines) if f'"{name}"' in t), 0)
    return None


def _places(ls: HfsmServer, uri: str, pos: lsp.Position) -> dict[str, list[lsp.Range]]:
    """Every place the name under the cursor is written: in this file, and for an outcome, in its
    callers' files too."""
    found = ls.context(uri)
    if found is None:
        return {}
    analysis, machine, lines = found
    name = navigation.name_at(machine, lines, pos)
    if name is None or name.kind == "behaviour":
        return {}
    places = {uri: navigation.occurrences(machine, lines, name)}
    if name.kind == "outcome" and analysis.library is not None:
        machines = _callers_in_view(ls, analysis)
        for path, rng in navigation.caller_occurrences(machines, machine.name, name.text, ls.lines):
            places.setdefault(from_fs_path(str(path)) or "", []).append(rng)
    return {u: rs for u, rs in places.items() if rs}


def _callers_in_view(ls: HfsmServer, analysis: Analysis) -> dict[str, MachineFile]:
    """The machines of this check and of every open document's check: callers may be either."""
    machines: dict[str, MachineFile] = {}
    for other in [analysis, *ls.state.analyses.values()]:
        if other.library is not None:
            for mf in other.library.machines.values():
                machines.setdefault(str(mf.path.resolve()), mf)
    return machines


def main() -> None:
    build().start_io()
