"""`--world sim` through `hfsm-run`: scenario files checked like machine files, the radio into the
mailboxes, the score in --json, the default outputs."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from hfsm.cli.run import main

Machine = Callable[[str, str], Path]
TALK = """
    outcomes: [done, timeout]
    timer: 5
    states:
      start:
        choose:
          - if: "agent.id == 'r1'"
            then: speak
          - else: listen
      speak: {do: send, with: {message: hi, data: {d: 1.5}}, on: {sent: done}}
      listen: {do: wait_for, with: {message: hi}, on: {received: done}}
"""


def run(capsys: pytest.CaptureFixture[str], *argv: object) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_radio_latency_delays_messages(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = machine("talk", TALK)
    out_dir = tmp_path / "out"
    code, out, _ = run(capsys, path, "--world", "sim", "--json", "--radio-latency", "0.5", "--out", out_dir)
    result = json.loads(out)
    assert code == 0
    assert result["agents"]["r2"] == {"outcome": "done", "outputs": {}, "time": 0.5}
    assert set(result["score"]) == {"success", "table_wall_distance", "dropped", "robot_collisions", "time"}
    assert sorted(p.suffix for p in out_dir.iterdir()) == [".jsonl", ".mp4", ".png"]


def test_a_lost_message_never_arrives(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = machine("talk", TALK)
    code, out, _ = run(capsys, path, "--json", "--radio-loss", "1", "--no-video", "--out", tmp_path, "--world", "sim")
    assert code == 0 and json.loads(out)["agents"]["r2"]["outcome"] == "timeout"


def test_bad_scenario_file_is_reported_at_its_positions(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scenario = tmp_path / "room.yaml"
    scenario.write_text("room: {width: 5.0, depth: 5.0}\ntable: {x: 0, lenght: 0.8}\nrobots:\n  R1: {x: 1, y: 1}\n")
    code, out, err = run(capsys, machine("talk", TALK), "--world", "sim", "--scenario", scenario)
    assert code == 2 and out == "" and "Traceback" not in err
    assert "room.yaml:2:15: error[E200]: unknown key 'lenght'; did you mean 'length'?" in err
    assert "room.yaml:4:3: error[E200]: bad name 'R1'" in err


@pytest.mark.parametrize(("flag", "value"), [("--scenario", "nowhere"), ("--image-size", "big"), ("--radio-loss", "2")])
def test_bad_world_arguments_exit_2(machine: Machine, capsys: pytest.CaptureFixture[str], flag: str, value: str) -> None:
    code, _, err = run(capsys, machine("talk", TALK), "--world", "sim", flag, value)
    assert code == 2 and "Traceback" not in err


@pytest.mark.parametrize("dt", ["0.01", "0.004"])
def test_simulated_time_keeps_up_with_any_dt(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path, dt: str
) -> None:
    wait = machine("pause", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 3}, on: {done: done}}\n")
    code, out, _ = run(capsys, wait, "--world", "sim", "--dt", dt, "--json", "--no-video", "--out", tmp_path / "o")
    result = json.loads(out)
    assert code == 0 and result["agents"]["r1"]["time"] == 3.0 and result["score"]["time"] == pytest.approx(3.0)


def test_an_unwritable_output_folder_is_exit_2(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, machine("talk", TALK), "--world", "sim", "--out", "/proc/nowhere")
    assert code == 2 and "cannot write in /proc/nowhere" in err


def test_the_score_is_the_scenario_task_s_and_about_robots_only_without_a_task(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    path = machine("talk", TALK)
    code, out, _ = run(capsys, path, "--world", "sim", "--no-video", "--out", tmp_path)
    assert code == 0 and "task: table_to_wall\nscore: success " in out
    bare = tmp_path / "bare.yaml"
    bare.write_text("robots:\n  r1: {x: -1.0, y: 0.5}\n  r2: {x: 1.0, y: -0.5}\n")
    code, out, _ = run(capsys, path, "--world", "sim", "--scenario", bare, "--no-video", "--out", tmp_path)
    assert code == 0 and "r2: ended in 'done'" in out and "score: robot_collisions 0, time " in out
    assert "task" not in out and "table" not in out and "success" not in out and "dropped" not in out
    code, out, _ = run(capsys, path, "--world", "sim", "--scenario", bare, "--json", "--no-video", "--out", tmp_path)
    assert code == 0 and set(json.loads(out)) == {"agents", "score"}
    assert set(json.loads(out)["score"]) == {"robot_collisions", "time"}
