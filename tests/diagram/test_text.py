from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from hfsm.diagram import text
from hfsm.model import Param, Retry


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
    assert text.value({"a": "b"}) == '{a: "b"}'


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
    assert text.timer("${params.limit}") == "params.limit s"  # no default: no value to show
    limit = {"limit": Param(type="float", default=30), "n": Param(type="int")}
    assert text.timer("${params.limit}", limit) == "params.limit (30 s)"
    assert text.timer("${params.limit * 2}", limit) == "params.limit * 2 (60 s)"
    assert text.timer("${params.n}", limit) == "params.n s"
    assert text.timer("${state.time}", limit) == "state.time s"
    assert text.params({}) == ""
    params = {"steps": Param(type="int", default=3), "role": Param(type="str")}
    assert text.params(params) == "(steps: int = 3, role: str)"
    assert text.condition(2, "vars.n < 0") == "2: vars.n < 0"
    assert text.retry(Retry(on=["failed", "error"], times=3), {}) == "retry \u00d73: failed, error"
    tries = {"tries": Param(type="int", default=2)}
    shown = text.retry(Retry(on=["failed"], times="${params.tries}", delay=1.5), tries)
    assert shown == "retry \u00d7params.tries (2), 1.5 s\napart: failed"


def test_conditions_are_wrapped_over_lines_never_cut() -> None:
    long = "abs(vars.left - vars.right) > params.difference * max(vars.left, vars.right)"
    shown = text.condition(1, long)
    assert text.ELLIPSIS not in shown
    assert shown.replace("\n", " ") == f"1: {long}"
    assert all(len(line) <= text.CONDITION_WIDTH for line in shown.split("\n"))
    assert text.labels(("done", "failed")) == "done | failed"
    assert text.labels((shown, "2: vars.n < 0")) == f"{shown}\n2: vars.n < 0"


def test_paragraphs_end_with_a_sentence() -> None:
    doc = "One two three. Four five six seven. " + "Eight nine ten eleven. " * 20
    lines = text.paragraph(doc, width=40, max_lines=3)
    assert len(lines) <= 3 and all(len(line) <= 40 for line in lines)
    shown = " ".join(lines)
    assert shown.startswith("One two three. Four five six seven.") and shown.endswith(". \u2026")
    whole = text.paragraph("word " * 100 + "end.", width=40, max_lines=3)  # one sentence: all of it
    assert " ".join(whole) == " ".join(["word"] * 100) + " end."
    assert text.paragraph("Short. Doc.") == ("Short. Doc.",)


@given(st.text(), st.integers(min_value=2, max_value=80))
def test_shorten_never_exceeds_its_width(s: str, width: int) -> None:
    assert len(text.shorten(s, width)) <= width


@given(
    st.text(alphabet=st.characters(blacklist_categories=("Cs",)), min_size=1),
    st.integers(min_value=5, max_value=60),
)
def test_wrap_keeps_every_word(s: str, width: int) -> None:
    flat = " ".join(s.split())
    wrapped = text.wrap(s, width)
    assert wrapped.replace("\n", " ") == (flat or s).replace("\n", " ")  # whitespace alone: as it is
    assert text.ELLIPSIS not in wrapped or text.ELLIPSIS in s
