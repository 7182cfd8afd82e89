"""Expressions that no input can break (hfsm.expr.guard): any size or depth is an ExprSyntaxError
at the characters at fault, never MemoryError, RecursionError, ValueError or a hang; and through
`hfsm-run FILE --check`, a positioned error, exit 2, no traceback, in bounded memory."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers import execute, write
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.expr import ExprSyntaxError, Names, Scope, compile_expr, guard, reads
from hfsm.values import compile_value

NAMES = Names(params=["x"], vars=["n", "l", "d"])

# Each hostile class of expression, built at a given size.
CLASSES: dict[str, Callable[[int], str]] = {
    "unary minus": lambda n: "-" * n + "1",
    "not": lambda n: "not " * n + "true",
    "sum": lambda n: "+".join(["1"] * n),
    "product": lambda n: " * ".join(["vars.n"] * n),
    "parentheses": lambda n: "(" * n + "1" + ")" * n,
    "lists": lambda n: "[" * n + "1" + "]" * n,
    "dicts": lambda n: "{'a': " * n + "1" + "}" * n,
    "calls": lambda n: "abs(" * n + "1" + ")" * n,
    "subscripts": lambda n: "vars.l" + "[0]" * n,
    "conditionals": lambda n: "1 if vars.n else " * n + "2",
    "comparisons": lambda n: " < ".join(["1"] * n),
    "and": lambda n: " and ".join(["true"] * n),
    "unclosed": lambda n: "(" * n,
    "digits": lambda n: "9" * n,
    "float digits": lambda n: "1." + "5" * n,
    "string": lambda n: "'" + "a" * n + "'",
    "name": lambda n: "a" * n,
    "attributes": lambda n: "vars" + ".n" * n,
    "inputs": lambda n: " + ".join(["in.x"] * n),
}
SIZES = st.one_of(st.integers(0, 300), st.integers(300, 3_000), st.integers(3_000, 100_000))


def outcome(text: str) -> ExprSyntaxError | None:
    try:
        compile_expr(text, NAMES)
    except ExprSyntaxError as exc:
        return exc
    return None


@pytest.mark.parametrize("kind", sorted(CLASSES))
@settings(max_examples=25, deadline=None)
@given(size=SIZES)
def test_any_size_compiles_or_is_a_positioned_error(kind: str, size: int) -> None:
    text = CLASSES[kind](size)
    error = outcome(text)
    if error is not None:
        assert error.start is not None and error.end is not None
        assert 0 <= error.start <= error.end <= len(text)
        assert len(str(error)) < 400  # a message quotes a short piece of the text, never all of it
    reads(text)  # never raises either


@pytest.mark.parametrize("kind", sorted(set(CLASSES) - {"name", "unclosed"}))
def test_past_the_limits_each_class_is_refused(kind: str) -> None:
    text = CLASSES[kind](20_000)
    error = outcome(text)
    assert error is not None
    assert "limit" in error.message, error.message


@pytest.mark.parametrize(
    ("text", "fragment", "at"),
    [
        ("(" * 101 + "1" + ")" * 101, "brackets nested more than 100", 100),
        ("+".join(["1"] * 200), "nested more than 100 deep", None),
        ("-" * 1_001 + "1", "more than 1,000 operators", 1_000),
        ("1 + " + "9" * 1_001, "a number literal of 1,001 digits", 4),
        ("x" * 10_001, "an expression of 10,001 characters", 0),
    ],
)
def test_each_limit_names_itself_at_the_character_past_it(text: str, fragment: str, at: int | None) -> None:
    error = outcome(text)
    assert error is not None and fragment in error.message
    if at is not None:
        assert error.start == at


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("${vars.n}" + "a" * 100_000, "a string with '${…}' of 100,009 characters"),
        ("${vars.n}" * 1_001, "more than 1,000 '${…}' in one string"),
        ("a ${vars.n + 1", "'${' without its closing '}'"),
    ],
)
def test_strings_holding_expressions_have_limits(text: str, fragment: str) -> None:
    with pytest.raises(ExprSyntaxError, match=re.escape(fragment)):
        compile_value(text, NAMES)
    assert compile_value("${vars.n}" * 1_000, NAMES).fn(Scope({}, {"n": 1}, "r")) == "1" * 1_000


def test_just_within_the_limits_compiles() -> None:
    assert outcome("(" * 99 + "1" + ")" * 99) is None
    assert outcome("+".join(["1"] * 90)) is None
    assert outcome("9" * guard.MAX_DIGITS) is None
    assert outcome("[" + ", ".join(["1"] * 2_000) + "]") is None  # long, but flat


@pytest.mark.parametrize(
    ("text", "char"),
    [
        ("vars.n + (1", "("),
        ("[1, 2", "["),
        ("vars.n + {'a': [1, 2}", "["),  # the bracket never closed, not the '}'
        ("f(']') + [1, (2]", "("),
        ("  in.x + (vars.n", "("),
        ("in.a + in.b + nope", "n"),
        ("sine(vars.n)", "s"),
        ("1 + 'é' + vars.zz", "v"),
    ],
)
def test_errors_point_at_the_character_at_fault(text: str, char: str) -> None:
    error = outcome(text)
    assert error is not None and error.start is not None
    assert text[error.start] == char, (error.message, error.start)


HOSTILE = {  # the string given to `with: {x: "…"}`
    "minus": "${" + "-" * 10_000 + "1}",
    "nots": "${" + "not " * 20_000 + "true}",
    "sum": "${" + "+".join(["1"] * 20_000) + "}",
    "brackets": "${" + "(" * 5_000 + "1" + ")" * 5_000 + "}",
    "digits": "${" + "9" * 100_000 + "}",
    "string": "${'" + "a" * 1_000_000 + "'}",
    "deep": "${" + "+".join(["1"] * 1_000) + "}",
    "unclosed": "${" + "a" * 3_000_000,
    "many": "${vars.x}" * 300_000,
}
MEASURE = """
import resource, subprocess, sys
done = subprocess.run(sys.argv[1:], capture_output=True, text=True)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({"code": done.returncode, "err": done.stderr, "rss_kb": usage.ru_maxrss,
                  "cpu": usage.ru_utime + usage.ru_stime}))
"""


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_check_of_a_hostile_file_is_a_positioned_error_in_bounded_memory(tmp_path: Path, name: str) -> None:
    path = tmp_path / f"h_{name}.yaml"
    path.write_text(
        "outcomes: [done]\nvars: {x: 0}\nstates:\n  s:\n    do: set\n"
        f'    with: {{x: "{HOSTILE[name]}"}}\n    on: {{done: done}}\n'
    )
    command = [sys.executable, "-c", "import json\n" + MEASURE, sys.executable, "-m", "hfsm.cli.run"]
    done = subprocess.run([*command, str(path), "--check"], capture_output=True, text=True, check=True)
    got = json.loads(done.stdout)
    assert got["code"] == 2, got["err"]
    assert "Traceback" not in got["err"]
    assert got["err"].startswith(f"{path}:6:"), got["err"][:300]
    assert "error[E314]" in got["err"]
    assert len(got["err"]) < 1_000
    assert got["rss_kb"] < 100 * 1024  # a bound, not a measurement: ~40 MB is usual
    assert got["cpu"] < 10  # a generous bound on CPU seconds (imports included), not a timing


@pytest.mark.parametrize(
    "where",
    [
        'do: wait\n    with: {seconds: "${%s}"}\n    on: {done: done}',
        'do: wait\n    with: {seconds: 1}\n    timer: "${%s}"\n    on: {done: done, timeout: done}',
        'do: set\n    with: {x: "${sqrt(%s)}"}\n    on: {done: done}',
        'do: set\n    with: {x: "${%s * 1.5}"}\n    on: {done: done}',
    ],
)
def test_an_integer_too_large_for_a_float_is_an_error_at_run_time(tmp_path: Path, where: str) -> None:
    huge = "9" * 400  # within the literal limit, beyond a float
    path = write(tmp_path, "m", f"outcomes: [done]\nvars: {{x: 0}}\nstates:\n  s:\n    {where % huge}\n")
    result, _ = execute(path)
    assert result.error is not None and "Traceback" not in result.error
    assert result.agents["robot"].outcome is None
