"""Values that expressions build are bounded: past a limit, the event `error` names it (hfsm.bounds)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from helpers import execute, write
from hypothesis import given
from hypothesis import strategies as st

from hfsm import bounds
from hfsm.expr import ExprSyntaxError, ExprValueError, Names, Scope, compile_expr
from hfsm.values import compile_value

NAMES = Names(params=(), vars=("a", "b", "l", "s", "d"))


def evaluate(source: str, **values: Any) -> Any:
    return compile_expr(source, NAMES)(Scope({}, values, "robot"))


GROW = """
    outcomes: [done]
    vars: {{l: [1], s: "ab", n: 3, d: {{}}, x: 1.5}}
    states:
      grow: {{do: set, with: {{{change}}}, on: {{done: pause}}}}
      pause: {{do: wait, with: {{seconds: 0.05}}, on: {{done: grow}}}}
"""


@pytest.mark.parametrize(
    ("change", "limit"),
    [
        ('l: "${vars.l + vars.l}"', "a list of more than 100,000 elements"),
        ('s: "${vars.s + vars.s}"', "a string of more than 100,000 characters"),
        ('s: "${vars.s}${vars.s}"', "a string of more than 100,000 characters"),
        ('n: "${vars.n * vars.n}"', "an integer of more than 1,000 digits"),
        ('l: "${[vars.l, vars.l]}"', "a value of more than 100,000 elements"),
        ('l: ["${vars.l}", "${vars.l}"]', "a value of more than 100,000 elements"),
        ('d: {k: "${vars.d}"}', "nested more than 100 deep"),
        ('x: "${vars.x * vars.x * 1e10}"', "not a finite number"),
    ],
)
def test_a_value_that_grows_every_tick_ends_in_an_error_naming_the_limit(
    tmp_path: Path, change: str, limit: str
) -> None:
    path = write(tmp_path, "grow", GROW.format(change=change))
    result, _ = execute(path, max_time=60)
    assert result.error is not None and limit in result.error
    assert result.time < 10  # simulated seconds: it stops at the limit, not at --max-time


def test_a_product_too_large_is_refused_before_it_is_computed() -> None:
    big = 10**999
    with pytest.raises(ExprValueError, match="1,000 digits"):
        evaluate("vars.a * vars.b", a=big, b=big)
    assert evaluate("vars.a * vars.b", a=big, b=1) == big


@pytest.mark.parametrize("source", ["1e999", "'" + "x" * (bounds.MAX_TEXT + 1) + "'", "9" * 1200])
def test_literals_past_a_limit_are_refused_at_load_time(source: str) -> None:
    with pytest.raises(ExprSyntaxError):
        compile_expr(source, NAMES)


def test_limits_allow_values_up_to_them() -> None:
    text = "x" * (bounds.MAX_TEXT // 2)
    assert len(evaluate("vars.s + vars.s", s=text)) == bounds.MAX_TEXT
    assert len(evaluate("vars.l + vars.l", l=[0] * (bounds.MAX_ITEMS // 2))) == bounds.MAX_ITEMS
    assert evaluate("vars.a * vars.a", a=10**499) == 10**998
    assert evaluate("vars.a + vars.b", a=1e308, b=-1e308) == 0.0


def test_a_float_from_a_huge_int_is_an_error() -> None:
    with pytest.raises(ExprValueError, match="too large"):
        evaluate("vars.a * 1.5", a=10**999)


@given(st.recursive(st.integers(0, 3), lambda kids: st.lists(kids, max_size=3), max_leaves=30))
def test_check_value_counts_elements_through_nesting(value: Any) -> None:
    def count(v: Any) -> int:
        return sum(1 + count(x) for x in v) if isinstance(v, list) else 0

    assert count(value) <= bounds.MAX_ITEMS and bounds.check_value(value) is value


def test_values_of_with_are_bounded() -> None:
    value = compile_value(["${vars.l}"] * 3, NAMES)
    with pytest.raises(ExprValueError, match="100,000 elements"):
        value.fn(Scope({}, {"l": [0] * 40_000}, "robot"))
