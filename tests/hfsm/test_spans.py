"""What a position points at in its line: the key, the value, the bracket, the name."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm.spans import span


def under(line: str, col: int) -> str:
    start, end = span(line, col)
    return line[start - 1 : end - 1]


@pytest.mark.parametrize(
    ("line", "col", "text"),
    [
        ("    do: wiat", 5, "do"),
        ("    do: wiat", 9, "wiat"),
        ("    do: wiat  # a comment", 9, "wiat"),
        ("  a: {do: wiat, on: {done: b}}", 11, "wiat"),
        ("  a: {do: wiat, on: {done: b}}", 6, "{do: wiat, on: {done: b}}"),
        ("  a: {do: wiat, on: {done: b}}", 22, "done"),
        ('      - if: "state.tim > 1"', 13, '"state.tim > 1"'),
        ("    with: {seconds: 1", 11, "{"),
        ('    with: {seconds: "${vars.cont + 1}"}', 24, "vars.cont"),
        ('      - if: "${vars.n > 1}"', 14, "${vars.n > 1}"),
        ("outcomes: [done, failed]", 18, "failed"),
        ("    text: it's a value  # here", 11, "it's a value"),
    ],
)
def test_a_position_underlines_what_starts_there(line: str, col: int, text: str) -> None:
    assert under(line, col) == text


def test_a_position_past_the_line_underlines_one_column() -> None:
    assert span("a: b", 9) == (5, 6)
    assert span("", 1) == (1, 2)


@given(st.text(alphabet="ab :{}[],#'\"$.-\t", max_size=40), st.integers(1, 45))
def test_a_span_starts_at_its_column_and_is_never_empty(line: str, col: int) -> None:
    start, end = span(line, col)
    assert start == min(col, len(line) + 1) and end > start
    assert end <= max(len(line) + 1, start + 1)
