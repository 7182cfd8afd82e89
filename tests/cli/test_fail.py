"""`hfsm-run --fail AGENT@S` (docs/REFERENCE.md#hfsm-run and #agents-that-fail): --json, --trace, exit codes, bad values."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from hfsm.cli.run import main
from hfsm.trace import read_jsonl

Machine = Callable[[str, str], Path]
WAIT = """
    outcomes: [done]
    states:
      w: {do: wait, with: {seconds: "${1 if agent.id == 'a' else 3}"}, on: {done: done}}
"""


def run(capsys: pytest.CaptureFixture[str], *argv: str | Path) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_json_trace_and_exit_0_when_the_others_end(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    trace = tmp_path / "t.jsonl"
    argv = (machine("m", WAIT), "--json", "--agents", "a,b", "--fail", "b@2", "--trace", trace)
    code, out, _ = run(capsys, *argv)
    assert code == 0
    assert json.loads(out) == {
        "agents": {
            "a": {"outcome": "done", "outputs": {}, "time": 1.0},
            "b": {"outcome": None, "outputs": {}, "time": 2.0, "failed": "--fail"},
        }
    }
    failed = [r for r in read_jsonl(trace) if r["kind"] == "failed"]
    assert failed == [{"t": 2.0, "agent": "b", "path": ["m", "w"], "kind": "failed", "reason": "--fail"}]


def test_exit_1_when_every_agent_failed(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, machine("m", WAIT), "--json", "--fail", "robot@0.5")
    assert code == 1
    assert json.loads(out) == {
        "outcome": None,
        "outputs": {},
        "time": 0.5,
        "failed": "--fail",
        "error": "every agent failed",
    }
    assert "error: every agent failed" in err


def test_repeatable(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, machine("m", WAIT), "--json", "--agents", "a,b", "--fail", "a@0", "--fail", "b@0.1")
    body = json.loads(out)
    assert code == 1
    assert [body["agents"][n]["time"] for n in "ab"] == [0.0, 0.1]


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("c@1", "--fail c@1: no agent named 'c' (agents: a, b)"),
        ("aa@1", "--fail aa@1: no agent named 'aa'; did you mean 'a'?"),
        ("a@-1", "argument --fail: 'a@-1': SECONDS must be a number >= 0, not '-1'"),
        ("a@soon", "argument --fail: 'a@soon': SECONDS must be a number >= 0, not 'soon'"),
        ("a@nan", "argument --fail: 'a@nan': SECONDS must be a number >= 0, not 'nan'"),
        ("a", "argument --fail: 'a': write AGENT@SECONDS, e.g. r2@60"),
    ],
)
def test_bad_values_are_exit_2_before_anything_runs(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path, value: str, message: str
) -> None:
    trace = tmp_path / "t.jsonl"
    try:
        code, _, err = run(capsys, machine("m", WAIT), "--agents", "a,b", "--fail", value, "--trace", trace)
    except SystemExit as exc:  # argparse's own exit for a value it cannot read
        code, err = int(str(exc.code)), capsys.readouterr().err
    assert code == 2
    assert message in err
    assert not trace.exists()
