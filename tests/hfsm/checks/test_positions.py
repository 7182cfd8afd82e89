"""Every finding points at the key or value that is wrong (issue 13: a few pointed elsewhere)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from hfsm.cli.run import main

Machine = Callable[[str, str], Path]


def check(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    code = main(list(argv))
    lines = [line for line in capsys.readouterr().err.splitlines() if "error[" in line or "warning[" in line]
    return code, lines


def test_a_badly_formed_state_name_is_reported_at_the_name(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    path = machine(
        "m", "outcomes: [done]\nstates:\n  ok: {do: wait, on: {done: done}}\n  Go-Home: {do: wait}\n"
    )
    code, lines = check(capsys, str(path), "--check")
    assert code == 2
    assert lines == [f"{path}:4:3: error[E200]: bad name 'Go-Home': names match ^[a-z][a-z0-9_]*$"]


def test_a_missing_param_of_the_top_machine_names_the_file(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        params:
          n: {type: int}
          s: {type: str}
        states:
          a: {do: wait, on: {done: done}}
        """,
    )
    code, lines = check(capsys, str(path), "--world", "none", "--param", "s=[1]")
    assert code == 2
    assert lines == [
        f"{path}:3:3: error[E307]: 'm' needs --param n=VALUE (int)",
        f"{path}:4:3: error[E306]: --param s: 'm' takes str, not [1]",
    ]


def test_block_style_findings_point_at_what_is_wrong(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    machine(
        "b",
        """
        outcomes: [done]
        states:
          x:
            parallel:
              r:
                do: a
                with: {data: {deep: ["${vars.z}"]}}
            join:
              - else: done
        """,
    )
    path = machine(
        "a",
        """
        outcomes: [done]
        states:
          a:
            do: b
            on: {done: c}
          c:
            choose:
              - if: "true"
                then: done
        """,
    )
    code, lines = check(capsys, str(path), "--check")
    assert code == 2
    folder = path.parent
    assert lines == [
        f"{folder / 'a.yaml'}:4:9: error[E312]: 'a' calls itself: a -> b -> a",
        f"{folder / 'a.yaml'}:7:5: error[E311]: choice 'c' must end with an 'else' branch",
        f"{folder / 'b.yaml'}:6:13: error[E312]: 'b' calls itself: b -> a -> b",
        f"{folder / 'b.yaml'}:7:16: error[E302]: unknown param 'data' of 'a' ('a' takes: nothing)",
        f"{folder / 'b.yaml'}:7:33: error[E314]: unknown variable 'z'",  # at vars.z, inside the string
    ]


def test_check_knows_the_world_and_a_retry_count_is_positive(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          a:
            do: log
            with: {text: "${in.battery}"}
            retry: {on: [done], times: 0}
            on: {done: done}
        """,
    )
    code, lines = check(capsys, str(path), "--check", "--world", "none")
    message = "'times' must be a whole number > 0 or a '${…}' expression, not 0"
    no_input = "error[E330]: the run's world declares no input 'in.battery' (it declares: none)"
    assert (code, lines) == (2, [f"{path}:5:21: {no_input}", f"{path}:6:32: error[E200]: {message}"])
    path.write_text(path.read_text().replace("times: 0", "times: 2"))
    code, lines = check(capsys, str(path), "--check", "--world", "none")
    message = "the run's world declares no input 'in.battery' (it declares: none)"
    assert (code, lines) == (2, [f"{path}:5:21: error[E330]: {message}"])


def test_schema_errors_of_rules_and_retries_name_the_right_keys(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    path = machine(
        "s",
        """
        outcomes: [done]
        states:
          p:
            parallel:
              r: {do: wait}
            join:
              - when: {r: done}
                then: done
                else: done
              - {when: {}, then: done}
          q:
            do: wait
            retry: {on: [done], times: 1, tries: 2}
            on: {done: done}
        """,
    )
    code, lines = check(capsys, str(path), "--check")
    assert code == 2
    assert lines == [
        f"{path}:9:9: error[E200]: unknown key 'else' (allowed: doc, then, when)",
        f"{path}:10:16: error[E200]: 'when' must have at least 1 entry, not none",
        f"{path}:13:35: error[E200]: unknown key 'tries'; did you mean 'times'?",
    ]
