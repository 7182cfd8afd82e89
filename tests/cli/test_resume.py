"""`hfsm-run FILE --resume TRACE@T`: the trace's flags and operator records up to T, the prefix
checked byte for byte as it is written, then the run goes on with the machine files as they are."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from hfsm.cli.run import main

CASES = Path(__file__).resolve().parents[1] / "spec" / "operator"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    for name in ("grasp.yaml", "grasp_object.yaml"):
        shutil.copy(CASES / name, tmp_path / name)
    (tmp_path / "ops.yaml").write_text("- {t: 1, agent: robot, do: force, event: done}\n")
    return tmp_path


def hfsm_run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, dict[str, object], str]:
    code = main([*argv, "--json", "--quiet", "--world", "none"])
    out, err = capsys.readouterr()
    return code, (json.loads(out) if out.strip() else {}), err


def lines(path: Path) -> list[str]:
    return path.read_text().splitlines()


def first(capsys: pytest.CaptureFixture[str], folder: Path) -> Path:
    trace = folder / "first.jsonl"
    code, result, _ = hfsm_run(
        capsys, str(folder / "grasp.yaml"), "--autonomy", "low", "--seed", "7",
        "--operator", str(folder / "ops.yaml"), "--trace", str(trace),
    )  # fmt: skip
    assert (code, result["outcome"], result["time"]) == (0, "carried", 1.0)
    return trace


def test_the_trace_begins_with_what_a_resume_needs(capsys: pytest.CaptureFixture[str], folder: Path) -> None:
    head = json.loads(lines(first(capsys, folder))[0])
    assert head["kind"] == "run" and head["agent"] is None
    assert head["args"] == ["--autonomy", "low", "--seed", "7", "--world", "none"]  # no outputs
    assert set(head["machines"]) == {"grasp", "grasp_object"}


def test_resume_replays_to_t_then_goes_on(capsys: pytest.CaptureFixture[str], folder: Path) -> None:
    trace = first(capsys, folder)
    (folder / "later.yaml").write_text("- {t: 0.7, agent: robot, do: accept}\n")
    again = folder / "again.jsonl"
    code, result, _ = hfsm_run(
        capsys, str(folder / "grasp.yaml"), "--resume", f"{trace}@0.5",
        "--operator", str(folder / "later.yaml"), "--trace", str(again),
    )  # fmt: skip
    assert (code, result["outcome"], result["time"]) == (0, "regrasped", 0.7)  # the trace's flags: level low
    old, new = lines(trace), lines(again)
    prefix = [line for line in old if json.loads(line)["t"] <= 0.5]
    assert new[: len(prefix)] == prefix  # byte for byte, header included
    resumed = json.loads(new[len(prefix)])
    assert resumed == {
        "t": 0.5,
        "agent": None,
        "path": [],
        "kind": "resume",
        "trace": str(trace),
        "at": 0.5,
        "edited": [],
    }


def test_resume_at_the_end_writes_the_same_trace(capsys: pytest.CaptureFixture[str], folder: Path) -> None:
    trace = first(capsys, folder)
    again = folder / "again.jsonl"
    code, result, _ = hfsm_run(
        capsys, str(folder / "grasp.yaml"), "--resume", f"{trace}@1", "--trace", str(again)
    )
    assert (code, result["outcome"]) == (0, "carried")
    assert lines(again)[: len(lines(trace))] == lines(trace)


def test_an_edit_off_the_active_path_is_accepted_and_recorded(
    capsys: pytest.CaptureFixture[str], folder: Path
) -> None:
    trace = first(capsys, folder)
    grasp = folder / "grasp.yaml"
    grasp.write_text(grasp.read_text().replace("with: {text: regrasp}", "with: {text: again}"))
    again = folder / "again.jsonl"
    code, _, _ = hfsm_run(capsys, str(grasp), "--resume", f"{trace}@0.5", "--trace", str(again))
    assert code == 1  # blocked: nobody answers after 0.5 s
    resumed = [json.loads(line) for line in lines(again) if '"resume"' in line]
    assert resumed[0]["edited"] == ["grasp"]


def test_an_edit_of_a_state_on_the_active_path_is_exit_2_naming_it(
    capsys: pytest.CaptureFixture[str], folder: Path
) -> None:
    trace = first(capsys, folder)
    grasp = folder / "grasp.yaml"
    inner = folder / "grasp_object.yaml"
    inner.write_text(
        inner.read_text()
        .replace("  reach:\n    do: wait", "  reach:\n    do: log\n    with: {text: hi}")
        .replace('    with: {seconds: "${params.seconds}"}\n', "")
    )
    code, _, err = hfsm_run(
        capsys, str(grasp), "--resume", f"{trace}@0.1", "--trace", str(folder / "x.jsonl")
    )
    assert code == 2
    assert "robot: grasp/grasp/reach: it calls 'log' now, not 'wait'" in err
    assert "Traceback" not in err


def test_a_change_before_t_is_a_clear_error(capsys: pytest.CaptureFixture[str], folder: Path) -> None:
    trace = first(capsys, folder)
    inner = folder / "grasp_object.yaml"
    inner.write_text(inner.read_text().replace("default: 0.2", "default: 0.3"))
    code, result, _ = hfsm_run(
        capsys, str(folder / "grasp.yaml"), "--resume", f"{trace}@0.5", "--trace", str(folder / "x.jsonl")
    )
    assert code == 1
    assert str(result["error"]).startswith(f"--resume: the run differs from {trace} at its line")


@pytest.mark.parametrize("spec", ["nowhere.jsonl@1", "first.jsonl", "first.jsonl@x", "first.jsonl@9"])
def test_bad_resume_arguments_are_exit_2(capsys: pytest.CaptureFixture[str], folder: Path, spec: str) -> None:
    first(capsys, folder)
    code, _, err = hfsm_run(capsys, str(folder / "grasp.yaml"), "--resume", str(folder / spec))
    assert code == 2
    assert "Traceback" not in err and ("--resume" in err or "E105" in err)
