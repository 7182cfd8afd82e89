"""`verify:` in a behaviour test: the case passes when every run is proved, and fails at its key
with the violation otherwise."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from verify_run import DATA

from hfsm.cli import test as test_cli

CASES = """\
agents: [a, b]
tests:
  survives_a_loss:
    machine: ask_until_answered
    verify: {loss: 1, fail: 1}
  once_is_not_enough:
    machine: ask_once
    verify: {loss: 1, goal: success}
"""


def test_a_verify_case_passes_or_names_the_violation(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    for name in ("ask_once", "ask_until_answered"):
        shutil.copy(DATA / f"{name}.yaml", tmp_path)
    (tmp_path / "ask.test.yaml").write_text(CASES)
    assert test_cli.main([str(tmp_path / "ask.test.yaml")]) == 1
    captured = capsys.readouterr()
    out = captured.out
    assert "1 passed, 1 failed" in captured.out + captured.err
    assert "ask.test.yaml:8:5: verify: failure_outcome (a): a ended in 'gave_up'" in out
    assert "message 'ask' a->b {'lost': True}" in out


def test_a_case_gives_expect_or_verify(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    shutil.copy(DATA / "ask_once.yaml", tmp_path)
    both = "agents: [a, b]\ntests:\n  both:\n    machine: ask_once\n    verify: {loss: 1}\n    expect: {outcome: done}\n"
    (tmp_path / "both.test.yaml").write_text(both)
    assert test_cli.main([str(tmp_path / "both.test.yaml")]) == 2
    assert "both.test.yaml:3:3: error[T330]" in capsys.readouterr().err


MEASURE = """\
tests:
  far:
    machine: measure
    stand_ins:
      sense: {after: 0.5, outcome: measured, outputs: {distance: 2}}
    verify: {}
  far_or_touching:
    machine: measure
    stand_ins:
      sense: [{outcome: measured, outputs: {distance: 2}}, {outcome: measured, outputs: {distance: 0}}]
    verify: {}
"""


def test_a_verify_case_takes_its_stand_ins_outputs(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """A case's stand-in scripts give the outputs its calls may end with: each step's is a choice."""
    for name in ("measure", "sense"):
        shutil.copy(DATA / f"{name}.yaml", tmp_path)
    (tmp_path / "measure.test.yaml").write_text(MEASURE)
    assert test_cli.main([str(tmp_path / "measure.test.yaml")]) == 1
    captured = capsys.readouterr()
    assert "1 passed, 1 failed" in captured.out + captured.err
    assert "measure.test.yaml:11:5: verify: error (robot): measure/plan: division by zero" in captured.out
    assert "'outputs': {'distance': 0}" in captured.out
