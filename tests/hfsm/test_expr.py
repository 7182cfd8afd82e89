from __future__ import annotations

from typing import Any

import pytest

from hfsm.expr import (
    ExprSyntaxError,
    ExprValueError,
    Names,
    Scope,
    compile_expr,
    format_number,
    to_text,
)
from hfsm.values import compile_value

NAMES = Names(params=["x", "items"], vars=["n", "data"])
SCOPE = Scope({"x": 2.5, "items": [1, 2, 3]}, {"n": 4, "data": {"d": 7}}, "r1")


def ev(text: str) -> Any:
    return compile_expr(text, NAMES)(SCOPE)


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("1 + 2 * 3", 7),
        ("vars.n // 3", 1),
        ("vars.n % 3", 1),
        ("params.x * 2", 5.0),
        ("vars.data['d']", 7),
        ("params.items[0]", 1),
        ("2 in params.items", True),
        ("not (vars.n > 3) or false", False),
        ("'big' if vars.n > 3 else 'small'", "big"),
        ("agent.id", "r1"),
        ("abs(-3) + min(1, 2) + max([4, 5]) + round(2.6) + len(params.items)", 3 + 1 + 5 + 3 + 3),
        ("true and null is None" if False else "null == None", True),
        ("[1, vars.n]", [1, 4]),
        ("{'a': vars.n}", {"a": 4}),
        ("'a' + 'b'", "ab"),
        ("1 < vars.n < 5", True),
    ],
)
def test_values(text: str, value: Any) -> None:
    assert ev(text) == value


@pytest.mark.parametrize(
    "text",
    [
        "__import__('os')",
        "params.x ** 2",
        "vars.n.real",
        "open('f')",
        "[x for x in params.items]",
        "lambda: 1",
        "params",
        "params.nope",
        "vars.nm",
        "agent.name",
        "foo",
        "1 +",
        "params.items[1:2]",
        "f'{vars.n}'",
    ],
)
def test_rejected_at_load(text: str) -> None:
    with pytest.raises(ExprSyntaxError):
        compile_expr(text, NAMES)


def test_suggestions() -> None:
    with pytest.raises(ExprSyntaxError, match="did you mean 'data'"):
        compile_expr("vars.dta", NAMES)


def test_machine_timers_may_not_read_vars() -> None:
    with pytest.raises(ExprSyntaxError, match=r"only params and agent\.id"):
        compile_expr("vars.n", Names(["x"], None))


@pytest.mark.parametrize(
    "text", ["1 / 0", "'a' + 1", "'a' * 3", "vars.data['zz']", "params.items[9]", "'a' < 1", "-'a'"]
)
def test_run_time_errors(text: str) -> None:
    with pytest.raises(ExprValueError):
        ev(text)


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (2.0, "2"),
        (0.1, "0.1"),
        (1e16, "1e+16"),
        (3, "3"),
        (True, "true"),
        (None, "null"),
        ("s", "s"),
        ([1, 2.0, "a"], '[1, 2, "a"]'),
        ({"k": False}, '{"k": false}'),
        (-1.5, "-1.5"),
    ],
)
def test_to_text(value: Any, text: str) -> None:
    assert to_text(value) == text


def test_format_number_reads_back() -> None:
    for x in (0.1, 1 / 3, 123456789.0, 1e-7, 2.5e300):
        assert float(format_number(x)) == x


def test_templates_at_any_depth() -> None:
    value = compile_value({"a": ["n=${vars.n}", "${vars.n}"], "b": "plain"}, NAMES)
    assert not value.constant
    assert value.fn(SCOPE) == {"a": ["n=4", 4], "b": "plain"}
    assert compile_value({"k": [1, "x"]}, NAMES).constant


def test_unclosed_template() -> None:
    with pytest.raises(ExprSyntaxError):
        compile_value("a ${vars.n", NAMES)


def test_braces_inside_expressions() -> None:
    assert compile_value("${ {'a': 1}['a'] }", NAMES).fn(SCOPE) == 1
