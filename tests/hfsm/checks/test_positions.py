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
    path = machine("m", "outcomes: [done]\nstates:\n  ok: {do: wait, on: {done: done}}\n  Go-Home: {do: wait}\n")
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
