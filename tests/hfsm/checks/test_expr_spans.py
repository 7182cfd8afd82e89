"""An expression's error points at the characters at fault inside the YAML string, whatever the
string's style (plain, quoted with escapes, block), with the span's end (Finding.end)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
import yaml
from hypothesis import given
from hypothesis import strategies as st

from hfsm.errors import Finding, UserError
from hfsm.load import load
from hfsm.registry import Registry
from hfsm.scalarpos import locate
from hfsm.yamlio import parse_text

Machine = Callable[[str, str], Path]

HEAD = "outcomes: [done]\nparams: {speed: {type: float, default: 1}}\nvars: {n: 0, d: {x: 1}}\nstates:\n"


def findings(machine: Machine, states: str) -> list[Finding]:
    path = machine("m", HEAD + states)
    with pytest.raises(UserError) as caught:
        load([path], registry=Registry())
    return [f for f in caught.value.findings if f.code == "E314"]


def at(machine: Machine, states: str) -> list[tuple[int, int, tuple[int, int] | None, str]]:
    """Each E314 as (line, col, end, the text of the file from the position to the end)."""
    text = (HEAD + states).splitlines()
    out = []
    for f in findings(machine, states):
        line = text[f.line - 1]
        stop = f.end[1] - 1 if f.end and f.end[0] == f.line else len(line)
        out.append((f.line, f.col, f.end, line[f.col - 1 : stop]))
    return out


def call(with_: str) -> str:
    return f"  s:\n    do: set\n    with:\n{with_}    on: {{done: done}}\n"


@pytest.mark.parametrize(
    ("with_", "shown"),
    [
        ('      n: "${vars.n + (1}"\n', "("),  # the bracket never closed
        ("      n: ${vars.n + sine(1)}\n", "sine"),  # plain
        ("      n: '${vars.n + ''a'' + spede}'\n", "spede"),  # single-quoted, '' inside
        ('      n: "\\t${vars.n + \\"a\\" + spede}"\n', "spede"),  # double-quoted, escapes
        ('      n: "\\u00e9 ${vars.d.x}"\n', "vars.d.x"),
        ("      n: 'found ${vars.nn} corners'\n", "vars.nn"),
        ('      n: "${vars.n} and ${vars.n +}"\n', ""),  # the end of the second expression
        ("      n: ${sqrt(1, 2)}\n", "sqrt(1, 2)"),
    ],
)
def test_the_error_points_inside_the_string(machine: Machine, with_: str, shown: str) -> None:
    (line, _col, end, text), *_ = at(machine, call(with_))
    assert line == 8 and end is not None
    assert text == shown


def test_multi_line_strings(machine: Machine) -> None:
    states = (
        "  s:\n    do: set\n    with:\n"
        "      n: >\n        ${vars.n +\n        sine(1)}\n"
        '      d: "${vars.n\n        + nope}"\n'
        "    on: {done: c}\n"
        "  c:\n    choose:\n"
        "      - if: |\n          vars.n > 1 and (\n            cuont > 2)\n        then: done\n"
        "      - else: done\n"
    )
    got = {text for _, _, _, text in at(machine, states)}
    assert got == {"sine", "nope", "cuont"}


def test_an_unclosed_template_is_at_its_opening(machine: Machine) -> None:
    (line, _col, _, text), *_ = at(machine, call('      n: "ab ${vars.n + 1"\n'))
    assert (line, text) == (8, "${")


def test_all_errors_at_once(machine: Machine) -> None:
    got = at(machine, call('      n: "${nope} ${vars.nn} ${sine(1)}"\n      d: "${[}"\n'))
    assert [text for _, _, _, text in got] == ["nope", "vars.nn", "sine", "["]


def test_an_expression_that_ends_too_early_points_just_after_it(machine: Machine) -> None:
    states = "  c:\n    choose:\n      - {if: vars.n >, then: done}\n      - else: done\n"
    (line, col, _, _), *_ = at(machine, states)
    assert (line, col) == (7, 22)  # the ',' after 'vars.n >'


def test_a_string_that_cannot_be_followed_stays_at_its_start(machine: Machine) -> None:
    states = call('      n: &a "${vars.n + nope}"\n')
    (line, col, end, _), *_ = at(machine, states)
    assert (line, col, end) == (8, 10, None)


STYLES = [None, "'", '"', "|", ">"]
TEXT = st.text(st.characters(blacklist_categories=("Cs", "Cc")) | st.sampled_from(["\n", "\t", "'", '"']))


@given(value=TEXT, style=st.sampled_from(STYLES), width=st.sampled_from([20, 80]))
def test_a_located_character_is_the_value_s_character(value: str, style: str | None, width: int) -> None:
    """Wherever a character of the value is placed, the file shows it there (or its escape, or a
    line break that folds into it); a value that cannot be followed gives None, never a wrong place."""
    text = yaml.dump({"k": value}, default_style=style, width=width, allow_unicode=True)
    doc = parse_text(text, "f.yaml")
    if doc.data.get("k") != value:
        return
    lines = text.splitlines(keepends=True)
    for offset in range(len(value)):
        placed = locate(text, doc.values[("k",)], value, (offset, offset + 1))
        if placed is None:
            continue
        (line, col), _ = placed
        shown = lines[line - 1][col - 1]
        assert shown == value[offset] or shown in "\\\n '\"" or (value[offset] in " \n" and shown in "\r\n")
