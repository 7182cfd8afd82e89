"""Reading a changed document again from the state that changed gives what reading it whole gives:
the same data, key and value positions, problems and errors, over random edits (hypothesis)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.errors import Finding, UserError
from hfsm.lsp import reparse
from hfsm.lsp.reparse import Reparser
from hfsm.yamlio import Document, parse_text

BASE = """\
doc: A machine to edit.
params:
  pause: {type: float, default: 0.5}
vars: {n: 0, items: [1, 2]}
outcomes: [done, failed]
states:
  first:
    do: wait
    with: {seconds: "${params.pause}"}
    on: {done: pick}
  # a comment between states
  pick:
    choose:
      - if: vars.n > 1 and vars.n != 3
        then: done
      - else: last

  last: {do: wait, with: {seconds: 1}, on: {done: done}}
  told:
    doc: |
      A block of text,
      on two lines.
    do: log
    with: {text: 'n is ${vars.n}'}
    on: {done: done}
timer: 30
"""
PIECES = ["a", "x", "0", " ", "  ", ":", ": ", ",", "{", "}", "[", "]", "#", "'", '"', "-", "\n", "\n  ", "\n    ",
          "&a ", "*a", "!t ", "|", ">", "${", "vars.n", "s9: {do: wait}", "\n  first: {}"]


def whole(text: str) -> tuple[str, object]:
    """What reading the text whole gives: its document's parts and its problems, or its errors."""
    kept: list[Finding] = []
    try:
        doc = parse_text(text, "m.yaml", kept=kept)
    except UserError as err:
        return "error", err.findings
    return "doc", (doc.data, doc.keys, doc.values, kept)


def again(reparser: Reparser, text: str) -> tuple[str, object]:
    kept: list[Finding] = []
    try:
        doc = reparser.parse(text, "m.yaml", kept=kept)
    except UserError as err:
        return "error", err.findings
    return "doc", (doc.data, doc.keys, doc.values, kept)


@st.composite
def edits(draw: st.DrawFn) -> list[tuple[int, int, str]]:
    """Edits inside the states' lines: (start, characters removed, text inserted)."""
    first = BASE.index("  first:")
    found = []
    for _ in range(draw(st.integers(1, 4))):
        start = draw(st.integers(first, len(BASE) - 12))
        found.append((start, draw(st.integers(0, 3)), draw(st.sampled_from(PIECES))))
    return found


@settings(max_examples=300, deadline=None)
@given(edits())
def test_a_document_read_again_from_what_changed_equals_it_read_whole(changes: list[tuple[int, int, str]]) -> None:
    reparser = Reparser()
    assert again(reparser, BASE) == whole(BASE)
    text = BASE
    for start, removed, inserted in changes:
        start = min(start, len(text))
        text = text[:start] + inserted + text[start + removed :]
        assert again(reparser, text) == whole(text)


def test_an_edit_inside_one_state_parses_that_state_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    parsed: list[int] = []

    def counted(text: str, file: str, *, kept: list[Finding] | None = None) -> Document:
        parsed.append(len(text.splitlines()))
        return parse_text(text, file, kept=kept)

    monkeypatch.setattr(reparse, "parse_text", counted)
    reparser = Reparser()
    reparser.parse(BASE, "m.yaml")
    edited = BASE.replace("seconds: 1}, on: {done: done}}", "seconds: 2}, on: {done: done}}\n  # a line more")
    doc = reparser.parse(edited, "m.yaml")
    assert parsed == [len(BASE.splitlines()), 2]
    assert doc.data["states"]["last"]["with"] == {"seconds": 2}
    assert doc.keys[("states", "told")] == (BASE.splitlines().index("  told:") + 2, 3)
    assert doc.data == parse_text(edited, "m.yaml").data
