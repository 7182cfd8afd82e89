"""`hfsm-test` cases script the operator (`operator:`, `autonomy:`) and expect held arcs (`held:`);
the machines are those of the conformance cases (tests/spec/operator/)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from hfsm.cli.test import main

CASES = Path(__file__).resolve().parents[2] / "spec" / "operator"


def run(tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str) -> tuple[int, str]:
    path = tmp_path / "grasp.test.yaml"
    path.write_text(f"machine: {CASES / 'grasp.yaml'}\n" + textwrap.dedent(text).lstrip(), encoding="utf-8")
    code = main([str(path), "-v"])
    out, err = capsys.readouterr()
    return code, out + err


def test_cases_script_the_operator_and_expect_holds(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, text = run(
        tmp_path,
        capsys,
        """
        autonomy: low
        tests:
          accepted:
            operator: [{t: 1, agent: robot, do: accept}]
            expect:
              outcome: regrasped
              time: 1
              held: [{state: grasp, event: failed, level: high, at: 0.2}]
          forced:
            operator: [{t: 0.5, agent: robot, do: force, event: done}]
            expect: {outcome: carried, time: 0.5, held: [{state: grasp, event: failed}]}
          trusted:
            autonomy: full
            expect: {outcome: regrasped, time: 0.2, held: []}
          nobody_answers:
            expect: {error: "holds 'failed' (needs autonomy high)", held: [{state: grasp, event: failed}]}
        """,
    )
    assert code == 0, text


def test_an_unexpected_hold_fails_the_case(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, text = run(
        tmp_path,
        capsys,
        """
        tests:
          none_expected:
            autonomy: off
            operator: [{t: 1, agent: robot, do: accept}]
            expect: {outcome: regrasped, held: []}
        """,
    )
    assert code == 1
    assert "robot: expected 0 held arcs; it held 1: [grasp:failed@0.2]" in text


def test_bad_operator_records_and_held_states_are_checked(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, text = run(
        tmp_path,
        capsys,
        """
        tests:
          bad:
            operator: [{t: 1, agent: robt, do: accept}, {t: 1, do: force, agent: robot}]
            expect: {held: [{state: grsp, event: failed}]}
        """,
    )
    assert code == 2
    assert "error[T315]: no agent named 'robt' in this run; did you mean 'robot'?" in text
    assert "error[T315]: 'force' needs the event to take" in text
    assert "error[T322]:" in text and "grsp" in text
