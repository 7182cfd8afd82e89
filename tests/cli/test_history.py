"""`hfsm-run --history FILE`: the top machine's `history` param, its file checked before anything runs."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers import finding_lines

from hfsm.cli.run import main

Machine = Callable[[str, str], Path]
KEEPS = """
    params:
      history: {type: str, default: ""}
      n: {type: int, default: 1}
    outcomes: [done]
    outputs: {history: "${params.history}"}
    states:
      a: {do: wait, with: {seconds: 0.1}, on: {done: done}}
"""
NONE = """
    params:
      n: {type: int, default: 1}
      gain: {type: float, default: 1.5}
    outcomes: [done]
    states:
      a: {do: wait, with: {seconds: 0.1}, on: {done: done}}
"""
GOOD = '{"version": 1, "pairs": [{"robots": ["r0", "r1"], "n_s": 1, "n_f": 0}], "robots": []}\n'


def run(capsys: pytest.CaptureFixture[str], *argv: object) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_history_sets_the_param(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = tmp_path / "h.json"
    path.write_text(GOOD, encoding="utf-8")
    code, out, _ = run(capsys, machine("m", KEEPS), "--world", "none", "--json", "--history", path)
    assert code == 0 and json.loads(out)["outputs"] == {"history": str(path)}


def test_a_missing_file_is_no_history_yet(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, out, _ = run(capsys, machine("m", KEEPS), "--world", "none", "--json", "--history", tmp_path / "new.json")
    assert code == 0 and json.loads(out)["outputs"] == {"history": str(tmp_path / "new.json")}
    assert run(capsys, machine("m", KEEPS), "--check", "--history", tmp_path / "new.json")[0] == 0


def test_a_machine_without_a_history_param_is_told_its_params(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    path = machine("m", NONE)
    code, out, err = run(capsys, path, "--history", "h.json")
    assert code == 2 and out == ""
    assert "\n".join(finding_lines(err)) == (f"{path}:1:1: error[E302]: --history: 'm' has no param 'history' to take the history "
                           "file ('m' takes: n, gain)")
    assert run(capsys, path, "--check", "--history", "h.json")[0] == 2


def test_history_given_twice_is_an_error(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, machine("m", KEEPS), "--history", "a.json", "--param", "history=b.json")
    assert code == 2 and "--history and --param history=... both give the history file" in err
    assert "Traceback" not in err


@pytest.mark.parametrize("route", ["--history", "--param"])
def test_a_bad_history_file_is_exit_2_at_its_positions_before_anything_runs(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path, route: str
) -> None:
    bad = tmp_path / "h.json"
    bad.write_text('{"version": 1,\n "pairs": [{"robots": ["r0"], "n_s": 1, "nf": 0}]}\n', encoding="utf-8")
    trace = tmp_path / "t.jsonl"
    given = ["--history", bad] if route == "--history" else ["--param", f"history={bad}"]
    for check in ([], ["--check"]):
        code, out, err = run(capsys, machine("m", KEEPS), *given, *check, "--trace", trace)
        assert code == 2 and out == "" and "Traceback" not in err
        assert finding_lines(err) == [
            f"{bad}:2:12: error[E340]: missing field 'n_f' (param 'history' of 'm')",
            f"{bad}:2:23: error[E340]: a pair names two different robots (param 'history' of 'm')",
            f"{bad}:2:41: error[E340]: unknown field 'nf'; did you mean 'n_f'? (param 'history' of 'm')",
        ]
    assert not trace.exists()  # nothing ran


def test_a_history_whose_folder_is_missing_cannot_be_written(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    where = tmp_path / "no" / "h.json"
    code, _, err = run(capsys, machine("m", KEEPS), "--check", "--history", where)
    assert code == 2 and f"{where}:1:1: error[E340]: the history is written at the end of the run" in err


def test_a_history_that_is_not_text_is_one_error(machine: Machine, capsys: pytest.CaptureFixture[str],
                                                 tmp_path: Path) -> None:
    bad = tmp_path / "h.json"
    bad.write_bytes(b'{"version": 1,\n "pairs": [\x01]}')
    code, _, err = run(capsys, machine("m", KEEPS), "--check", "--history", bad)
    assert code == 2 and err.strip().startswith(f"{bad}:2:12: error[E340]: not valid JSON: character U+0001")
    bad.write_bytes(b"\xff\xfe")
    code, _, err = run(capsys, machine("m", KEEPS), "--check", "--history", bad)
    assert code == 2 and f"{bad}:1:1: error[E340]: cannot read the history file" in err
