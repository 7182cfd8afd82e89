"""The functions of expressions (hfsm.expr.funcs): values, domain errors as run-time errors (the event
`error`), names and arity checked when the file is loaded."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm.expr import ExprSyntaxError, ExprValueError, Names, Scope, compile_expr
from hfsm.expr.funcs import FUNCS

NAMES = Names(params=["a"], vars=["x", "y", "l", "s"])


def ev(text: str, **values: Any) -> Any:
    return compile_expr(text, NAMES)(Scope({"a": 0}, values, "r1"))


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("sum([1, 2, 3.5])", 6.5),
        ("sum([])", 0),
        ("sorted([3, 1, 2.5])", [1, 2.5, 3]),
        ("sorted(['b', 'a'])", ["a", "b"]),
        ("any([0, false, 'x'])", True),
        ("all([1, true, 'x'])", True),
        ("all([])", True),
        ("any([])", False),
        ("sqrt(16)", 4.0),
        ("hypot(3, 4)", 5.0),
        ("hypot(2, 3, 6)", 7.0),
        ("atan2(1, 1)", math.pi / 4),
        ("degrees(atan2(0, -1))", 180.0),
        ("radians(180)", math.pi),
        ("floor(-1.5)", -2),
        ("ceil(1.2)", 2),
        ("floor(7)", 7),
        ("round(sin(radians(30)), 6)", 0.5),
        ("round(cos(0))", 1),
        ("round(tan(radians(45)), 9)", 1.0),
        ("round(degrees(asin(1)))", 90),
        ("round(degrees(acos(0)))", 90),
        ("round(degrees(atan(1)))", 45),
        ("min(3, 1, 2) + max([1, 5])", 6),
        ("min(['b', 'a'])", "a"),
    ],
)
def test_values(text: str, value: Any) -> None:
    got = ev(text)
    assert got == pytest.approx(value) if isinstance(value, float) else got == value
    assert type(got) is type(value)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("sqrt(-1)", "sqrt(): an argument outside the function's domain"),
        ("asin(2)", "asin(): an argument outside the function's domain"),
        ("acos(-1.5)", "acos(): an argument outside"),
        ("atan2('a', 1)", "atan2() takes numbers, not str"),
        ("sin(true)", "sin() takes numbers, not bool"),
        ("sum([1, 'a'])", "sum() takes numbers, not str"),
        ("sum(3)", "sum() takes a list, not int"),
        ("sorted([1, 'a'])", "sorted() of a mix of int, str"),
        ("sorted([[1], [2]])", "sorted() of a mix of list"),
        ("min([])", "min() of an empty list"),
        ("max(1, 'a')", "max() of a mix of int, str"),
        ("any(3)", "any() takes a list, not int"),
        ("floor(null)", "floor() takes numbers, not null"),
        ("sqrt(vars.x)", "sqrt() takes numbers, not str"),
        ("sin(vars.y)", "a number too large for a float"),
        ("hypot(1.5e308, 1.5e308)", "hypot(): "),
        ("degrees(1e308)", "not a finite number"),
        ("sum([1e308, 1e308])", "not a finite number"),
        ("round(1.5, 'a')", "round() takes a number"),
    ],
)
def test_domain_errors_are_run_time_errors(text: str, message: str) -> None:
    with pytest.raises(ExprValueError, match=re.escape(message)):
        ev(text, x="text", y=10**400)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("sqrt()", "sqrt() takes 1 argument, not 0"),
        ("atan2(1)", "atan2() takes 2 arguments, not 1"),
        ("hypot(1)", "hypot() takes at least 2 arguments, not 1"),
        ("round(1, 2, 3)", "round() takes 1 to 2 arguments, not 3"),
        ("min()", "min() takes at least 1 arguments, not 0"),
        ("sine(1)", "unknown function 'sine'; did you mean 'sin'?"),
        ("sqr(1)", "unknown function 'sqr'; did you mean 'sqrt'?"),
        ("exp(1)", "unknown function 'exp'"),
        ("sorted([1], reverse=true)", "'sorted()' takes plain arguments only"),
        ("vars.l.append(1)", "cannot be called"),
    ],
)
def test_names_and_arity_at_load_time(text: str, message: str) -> None:
    with pytest.raises(ExprSyntaxError, match=re.escape(message)) as caught:
        compile_expr(text, NAMES)
    assert caught.value.start is not None


def test_sin_is_a_function_now() -> None:
    assert ev("sin(0)") == 0.0  # once told "did you mean 'min'?"


def test_every_function_is_listed_in_the_reference() -> None:
    page = (Path(__file__).resolve().parents[2] / "docs" / "REFERENCE.md").read_text()
    for name in FUNCS:
        assert f"`{name}(" in page, name


NUMBERS = st.one_of(
    st.integers(-(10**30), 10**30),
    st.floats(allow_nan=False, allow_infinity=False),
    st.integers(-(10**999), 10**999),
)


@given(name=st.sampled_from(sorted(FUNCS)), args=st.lists(NUMBERS, min_size=1, max_size=3))
def test_any_numbers_give_a_finite_value_or_a_run_time_error(name: str, args: list[Any]) -> None:
    func = FUNCS[name]
    if len(args) < func.least or (func.most is not None and len(args) > func.most):
        return
    text = f"{name}({', '.join(f'vars.l[{i}]' for i in range(len(args)))})"
    try:
        got = ev(text, l=args)
    except ExprValueError:
        return
    if isinstance(got, float):
        assert math.isfinite(got)
