"""Definition, references and rename in process (the server's handlers, without its stdio)."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types as lsp

from hfsm.lsp.analysis import Settings, Workspace
from hfsm.lsp.server import HfsmServer, _definition, _places

MACHINE = """\
params:
  limit: {type: float, default: 2.0}
vars: {count: 0}
outcomes: [done]
states:
  look:
    do: scan_for_table
    save: {count: seen}
    on: {found: rest, not_found: rest}
  rest:
    do: wait
    with: {seconds: "${params.limit + vars.count}"}
    on: {done: done}
"""


@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> tuple[HfsmServer, Path]:
    path = tmp_path_factory.mktemp("nav") / "m.yaml"
    path.write_text(MACHINE)
    ls = HfsmServer(Workspace(Settings()))
    ls.state.set_text(path, MACHINE)
    ls.state.analyse(path)
    return ls, path


def test_a_primitive_goes_to_its_python_function(server: tuple[HfsmServer, Path]) -> None:
    ls, path = server
    found = _definition(ls, path.as_uri(), lsp.Position(6, 10))
    assert found is not None and found.uri.endswith("hfsm_behaviours/approach/search.py")
    line = Path(found.uri.removeprefix("file://")).read_text().splitlines()[found.range.start.line]
    assert line.startswith("def scan_for_table(")


def test_a_built_in_goes_to_its_declaration(server: tuple[HfsmServer, Path]) -> None:
    ls, path = server
    found = _definition(ls, path.as_uri(), lsp.Position(10, 9))
    assert found is not None and found.uri.endswith("hfsm/builtins.py")


def test_a_var_is_renamed_in_its_declaration_its_saves_and_its_expressions(
    server: tuple[HfsmServer, Path],
) -> None:
    ls, path = server
    places = _places(ls, path.as_uri(), lsp.Position(2, 8))
    assert [(r.start.line, r.start.character, r.end.character) for r in places[path.as_uri()]] == [
        (2, 7, 12), (7, 11, 16), (11, 43, 48)
    ]  # fmt: skip


def test_a_param_is_found_from_an_expression(server: tuple[HfsmServer, Path]) -> None:
    ls, path = server
    places = _places(ls, path.as_uri(), lsp.Position(11, 30))
    assert [(r.start.line, r.start.character) for r in places[path.as_uri()]] == [(1, 2), (11, 30)]
    found = _definition(ls, path.as_uri(), lsp.Position(11, 30))
    assert found is not None and found.range.start.line == 1
