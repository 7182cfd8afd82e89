from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from hfsm.diagram import text
from hfsm.model import Param


def test_values_read_as_in_the_machine_file() -> None:
    assert text.value("${vars.role}") == "vars.role"
    assert text.value("leader") == '"leader"'
    assert text.value("found ${vars.n}") == '"found ${vars.n}"'
    assert text.value(2.0) == "2"
    assert text.value(0.1) == "0.1"
    assert text.value(True) == "true"
    assert text.value(None) == "null"
    assert text.value([1, 2]) == "[1, 2]"
    assert text.value({"hits": "${vars.hits + 1}"}) == "{hits: vars.hits\u2026"
    assert text.value({"a": "b"}) == "{a: \"b\"}"


def test_long_values_are_cut_with_an_ellipsis() -> None:
    shown = text.value("x" * 100)
    assert len(shown) == text.VALUE_WIDTH
    assert shown.endswith(text.ELLIPSIS)


def test_a_call_breaks_after_commas() -> None:
    assert text.call("wait", {}) == ("wait()",)
    assert text.call("wait", {"seconds": 1}) == ("wait(seconds=1)",)
    lines = text.call("send", {"message": "way_cleared", "to": "others", "data": {"d": 1}})
    assert lines[0].startswith("send(message=") and lines[-1].endswith(")")
    assert all(len(line) <= text.LINE_WIDTH + 2 for line in lines)


def test_timers_params_and_conditions() -> None:
    assert text.timer(30) == "30 s"
    assert text.timer(0.5) == "0.5 s"
    assert text.timer("${params.limit}") == "params.limit s"
    assert text.params({}) == ""
    params = {"steps": Param(type="int", default=3), "role": Param(type="str")}
    assert text.params(params) == "(steps: int = 3, role: str)"
    assert text.condition(2, "vars.n < 0") == "2: vars.n < 0"


def test_paragraphs_are_wrapped_and_bounded() -> None:
    lines = text.paragraph("word " * 200, width=40, max_lines=3)
    assert len(lines) == 3
    assert all(len(line) <= 40 for line in lines)


@given(st.text(), st.integers(min_value=2, max_value=80))
def test_shorten_never_exceeds_its_width(s: str, width: int) -> None:
    assert len(text.shorten(s, width)) <= width
