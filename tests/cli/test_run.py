"""`hfsm-run` as users meet it: flags, output, exit codes (docs/REFERENCE.md#hfsm-run)."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers import finding_lines

from hfsm.cli.run import main

Machine = Callable[[str, str], Path]
ROOT = Path(__file__).resolve().parents[2]
ONE = """
    params:
      n: {type: int}
      gain: {type: float, default: 1.5}
    outcomes: [done]
    outputs: {n: "${params.n}", gain: "${params.gain}"}
    states:
      a: {do: wait, with: {seconds: 0.2}, on: {done: done}}
"""


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_json_for_one_agent(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, machine("m", ONE), "--json", "--param", "n=3", "--param", "gain=2")
    assert code == 0
    assert json.loads(out) == {"outcome": "done", "outputs": {"n": 3, "gain": 2.0}, "time": 0.2}


def test_json_for_several_agents_and_errors(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          a:
            choose:
              - {if: "agent.id == 'x'", then: bad}
              - {else: nap}
          bad: {do: wait, with: {seconds: "${1 / 0}"}, on: {done: done}}
          nap: {do: wait, with: {seconds: 5}, on: {done: done}}
    """,
    )
    code, out, err = run(capsys, path, "--json", "--agents", "x,y")
    body = json.loads(out)
    assert code == 1
    assert body["error"] == "m/bad: division by zero in '1 / 0'"
    assert body["agents"]["y"] == {"outcome": None, "outputs": {}, "time": 0.0}
    assert "Traceback" not in err


def test_required_param_missing_is_exit_2(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, machine("m", ONE))
    assert code == 2 and "needs --param n=VALUE" in err


@pytest.mark.parametrize(
    ("arg", "text"), [("n=x", "takes int"), ("m=1", "has no param 'm'"), ("n", "NAME=VALUE")]
)
def test_bad_params(machine: Machine, capsys: pytest.CaptureFixture[str], arg: str, text: str) -> None:
    code, _, err = run(capsys, machine("m", ONE), "--param", arg)
    assert code == 2 and text in err
    code, _, err = run(capsys, machine("m", ONE), "--param", arg, "--check")  # --check checks them too
    assert code == 2 and text in err


def test_check_checks_the_scenario_given(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    top = str(ROOT / "machines" / "clear_room.yaml")
    code, _, err = run(capsys, top, "--scenario", "room_3_tabels", "--check")
    assert code == 2 and "did you mean 'room_3_tables'?" in err
    bad = tmp_path / "room.yaml"
    bad.write_text("room: {width: 3, depth: -2}\n", encoding="utf-8")
    code, _, err = run(capsys, top, "--scenario", str(bad), "--check")
    assert code == 2 and f"{bad}:1:25: error[E200]: 'depth' must be > 1.5" in err
    assert f"{bad}:1:1: error[E200]: missing required key 'robots'" in err  # every error at once
    assert run(capsys, top, "--scenario", "room_3_tables", "--check")[0] == 0


def test_check_and_strict(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    path = machine(
        "m", "outcomes: [done, never]\nstates:\n  a: {do: wait, with: {seconds: 1}, on: {done: done}}\n"
    )
    assert run(capsys, path, "--check")[0] == 0
    code, _, err = run(capsys, path, "--check", "--strict")
    assert code == 2 and "error[W401]: outcome 'never' is never reached" in err


def test_bad_file_lists_every_error_with_positions(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    path = machine(
        "m", "outcomes: [done]\nstates:\n  a: {do: wiat, on: {done: b}}\n  b: {do: wait, on: {dne: done}}\n"
    )
    code, out, err = run(capsys, path, "--json")
    assert code == 2 and out == ""
    lines = finding_lines(err)
    assert lines[0].endswith("m.yaml:3:11: error[E300]: unknown behaviour 'wiat'; did you mean 'wait'?")
    assert len(lines) == 3


def test_max_time_and_trace(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: 9}, on: {done: done}}\n")
    trace = tmp_path / "t.jsonl"
    code, out, _ = run(capsys, path, "--max-time", "1", "--json", "--trace", trace)
    assert code == 1 and json.loads(out)["time"] == 1.0
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    assert [r["kind"] for r in records] == ["run", "enter", "enter", "exit", "exit"]


def test_schema(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "--schema")
    schema = json.loads(out)
    assert code == 0 and schema["title"] == "hfsm machine" and "states" in schema["properties"]


def test_committed_schema_is_current(capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = run(capsys, "--schema")
    assert (ROOT / "docs" / "machine.schema.json").read_text() == out, (
        "run: hfsm-run --schema > docs/machine.schema.json"
    )


@pytest.mark.parametrize(
    "argv", [["--dt", "0"], ["--max-time", "-1"], ["--agents", "A,b"], ["--world", "mars"], []]
)
def test_bad_arguments_exit_2(machine: Machine, argv: list[str]) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: 1}, on: {done: done}}\n")
    args = [sys.executable, "-m", "hfsm.cli.run", *([str(path)] if argv else []), *argv]
    done = subprocess.run(args, capture_output=True, text=True, check=False)
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr


def test_not_utf8_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "m.yaml"
    path.write_bytes(b"outcomes: [done]\nstates: \xff\n")
    code, _, err = run(capsys, path)
    assert code == 2 and "m.yaml:2:9: error[E104]" in err


def test_stdout_holds_only_the_json_even_when_plugins_print() -> None:
    args = [sys.executable, "-m", "hfsm.cli.run", str(ROOT / "examples" / "hello.yaml"), "--json"]
    done = subprocess.run(args, capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout) == {"outcome": "done", "outputs": {"count": 2}, "time": 0.5}


def test_world_none_registers_no_simulator_primitive(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    machine("land_table", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 1}, on: {done: done}}\n")
    top = machine("top", "outcomes: [done]\nstates:\n  a: {do: land_table, on: {done: done}}\n")
    code, out, _ = run(capsys, top, "--world", "none", "--json")
    assert code == 0 and json.loads(out)["outcome"] == "done"


def test_a_simulator_primitive_under_world_none_is_named_as_such(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    top = machine("top", "outcomes: [done]\nstates:\n  a: {do: land_table, on: {landed: done, failure: done}}\n")
    code, _, err = run(capsys, top, "--world", "none")
    assert code == 2 and "error[E300]: 'land_table' is a primitive of --world sim" in err


def test_an_unwritable_trace_is_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, ROOT / "examples" / "hello.yaml", "--trace", "/proc/nowhere/t.jsonl")
    assert code == 2 and "--trace: cannot write /proc/nowhere/t.jsonl" in err


PATIENCE = """
    params:
      s: {type: float, default: 0.5}
    outcomes: [done, gave_up]
    failures: [gave_up]
    states:
      a: {do: wait, with: {seconds: "${params.s}"}, timer: 1, on: {done: done, timeout: gave_up}}
"""


@pytest.mark.parametrize(("text", "args", "code", "said"), [
    (PATIENCE, [], 0, ""),
    (PATIENCE, ["--param", "s=2"], 3, "robot ended in the failure outcome 'gave_up' (--fail-exit: exit 3)"),
    ("outcomes: [done]\ntimer: 1\nstates:\n  a: {do: wait, with: {seconds: 2}, on: {done: done}}\n", [], 3,
     "robot ended in the failure outcome 'timeout'"),
])
def test_fail_exit_makes_a_failure_outcome_exit_3(tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str,
                                                 args: list[str], code: int, said: str) -> None:
    path = tmp_path / "patience.yaml"
    path.write_text(text)
    assert run(capsys, path, "--quiet", *args)[0] == 0  # without the flag a failure outcome is an outcome
    got, _, err = run(capsys, path, "--quiet", "--fail-exit", *args)
    assert got == code and said in err


def test_a_machine_by_name_and_a_misspelt_name(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    (tmp_path / "patience.yaml").write_text(PATIENCE)
    code, _, err = run(capsys, "patience", "--lib", tmp_path, "--check")
    assert code == 0 and "patience.yaml: ok" in err
    code, _, err = run(capsys, "patiense", "--lib", tmp_path, "--check")
    assert code == 2 and "'patiense' is no file here, nor a machine in" in err and "did you mean 'patience'?" in err


def test_new_plugin_writes_the_template(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, err = run(capsys, "--new-plugin", tmp_path / "mine")
    template = ROOT / "examples" / "plugin_template"
    made = sorted(p.relative_to(tmp_path / "mine") for p in (tmp_path / "mine").rglob("*") if p.is_file())
    kept = sorted(p.relative_to(template) for p in template.rglob("*")
                  if p.is_file() and "__pycache__" not in p.parts and ".egg-info" not in str(p))
    assert code == 0 and made == kept and "pip install -e" in err
    code, _, err = run(capsys, "--new-plugin", tmp_path / "mine")
    assert code == 2 and "already there" in err


def test_schema_says_where_the_installed_copy_is(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "--schema")
    installed = ROOT / "hfsm" / "schemas" / "machine.schema.json"
    assert code == 0 and json.loads(out) == json.loads(installed.read_text())
    assert f"# yaml-language-server: $schema={installed}" in err
