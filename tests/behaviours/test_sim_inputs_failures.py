"""The sim world's inputs (read from what a robot senses) and its failures (scenario, battery, --fail)."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest
from carry_scene import DATA, at_table, run_in_scene
from helpers import hfsm_run

Machine = Callable[[str, str], Path]

# r1 looks at the table along +x; r2 stands to r1's left, looking at r1 (the table off to its side).
SCENE = """
room: {width: 5.0, depth: 5.0}
table: {x: 0.0, y: 0.0}
robots:
  r1: {x: -1.5, y: 0.0, yaw: 0}
  r2: {x: -1.5, y: 1.5, yaw: -90}
battery: {start: 0.5, idle: 0.01, walk: 0.0}
"""
SENSE = """
    vars: {seen: {}}
    outcomes: [done]
    outputs: {seen: "${vars.seen}"}
    states:
      pause: {do: wait, with: {seconds: 1}, on: {done: look}}
      look:
        do: set
        with:
          seen:
            table: "${in.table_in_view}"
            bearing: "${in.table_bearing}"
            tables: "${in.tables_in_view}"
            partner: "${in.partner_in_view}"
            pose: "${in.pose}"
            battery: "${in.battery}"
            gives: ["${in.hand_give_left}", "${in.hand_give_right}"]
            holding: "${in.holding}"
            delay: "${in.radio_delay}"
        on: {done: done}
"""
HEAR = """
    vars: {before: -1.0}
    outcomes: [done]
    outputs: {before: "${vars.before}", after: "${in.radio_delay}"}
    states:
      start: {do: set, with: {before: "${in.radio_delay}"}, on: {done: meet}}
      meet: {do: barrier, with: {name: go}, on: {passed: done}}
"""


def test_inputs_are_what_each_robot_senses(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scene = tmp_path / "scene.yaml"
    scene.write_text(SCENE)
    argv = (machine("sense", SENSE), "--world", "sim", "--scenario", scene, "--json", "--no-video", "--out", tmp_path, "--quiet")
    code, out, _ = hfsm_run(capsys, *argv)
    agents = json.loads(out)["agents"]
    assert code == 0
    r1, r2 = agents["r1"]["outputs"]["seen"], agents["r2"]["outputs"]["seen"]
    assert (r1["table"], r1["partner"]) == (True, False)
    assert abs(r1["bearing"]) < 3.0
    assert (r2["table"], r2["bearing"], r2["partner"]) == (False, None, True)
    (top,) = r1["tables"]  # 1.5 m ahead, its long axis along r1's view, 0.8 x 0.5 m
    assert (top["x"], top["y"], top["heading"]) == pytest.approx((1.5, 0.0, 0.0), abs=0.08)
    assert (top["length"], top["width"]) == pytest.approx((0.8, 0.5), abs=0.1)
    assert r2["tables"] == []
    for seen in (r1, r2):
        assert seen["pose"] == {"x": 0.0, "y": 0.0, "yaw": 0.0}  # standing still: odometry at its start
        assert seen["battery"] == pytest.approx(0.49)
        assert (seen["gives"], seen["holding"]) == ([0.0, 0.0], False)
        assert seen["delay"] == 0.0  # nothing heard yet


def test_radio_delay_is_what_the_latest_notice_took(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    argv = (machine("hear", HEAR), "--world", "sim", "--json", "--no-video", "--out", tmp_path, "--quiet",
            "--radio-latency", "0.7")
    code, out, _ = hfsm_run(capsys, *argv)
    agents = json.loads(out)["agents"]
    assert code == 0
    assert [agents[r]["outputs"] for r in ("r1", "r2")] == [{"before": 0.0, "after": 0.7}] * 2


def test_check_knows_the_sim_inputs(machine: Machine, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = hfsm_run(capsys, machine("sense", SENSE), "--world", "sim", "--check")
    assert code == 0, err


def test_fail_in_the_sim_world(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    pause = machine("pause", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 2}, on: {done: done}}\n")
    argv = (pause, "--world", "sim", "--json", "--no-video", "--out", tmp_path, "--fail", "r2@1", "--quiet")
    code, out, _ = hfsm_run(capsys, *argv)
    agents = json.loads(out)["agents"]
    assert code == 0
    assert agents["r2"] == {"outcome": None, "outputs": {}, "time": 1.0, "failed": "--fail"}
    assert agents["r1"]["outcome"] == "done"


def test_an_empty_battery_fails_the_robot(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    scene = tmp_path / "scene.yaml"
    scene.write_text(SCENE.replace("idle: 0.01", "idle: 0.25"))
    pause = machine("pause", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 3}, on: {done: done}}\n")
    code, out, _ = hfsm_run(capsys, pause, "--scenario", scene, "--json", "--no-video", "--out", tmp_path, "--world", "sim")
    agents = json.loads(out)["agents"]
    assert code == 1 and json.loads(out)["error"] == "every agent failed"
    assert {n: (a["time"], a["failed"]) for n, a in agents.items()} == {
        "r1": (2.0, "battery empty"),
        "r2": (2.0, "battery empty"),
    }


@pytest.mark.slow
def test_a_robot_that_fails_mid_carry_drops_the_table_and_goes_silent() -> None:
    scene = at_table()
    scene["failures"] = [{"robot": "r2", "at": 20.0, "reason": "fell"}]  # carrying, between 13 and 25 s
    run = run_in_scene(DATA / "carry_only.yaml", scene, max_time=120)
    r2 = run.result.agents["r2"]
    assert (r2.outcome, r2.time, r2.failed) == (None, 20.0, "fell")
    assert run.outcome("r1") == "failure"  # r1 felt the table go and gave up
    assert run.score["dropped"] and not run.score["success"]
    assert not [r for r in run.records if r["agent"] == "r2" and r["t"] > 20.0]
    assert not [r for r in run.records if r["kind"] == "receive" and r["agent"] == "r2" and r["t"] >= 20.0]


def test_scenario_failures_are_checked_at_their_positions(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scene = tmp_path / "scene.yaml"
    scene.write_text(SCENE + "failures:\n  - {robot: r3, at: 5}\n")
    code, _, err = hfsm_run(capsys, machine("sense", SENSE), "--world", "sim", "--scenario", scene)
    assert code == 2
    assert "scene.yaml:9:13: error[E200]: no robot named 'r3' in the scenario (robots: r1, r2)" in err
    scene.write_text(SCENE + "failures:\n  - {robot: r2, at: -5, why: x}\n")
    code, _, err = hfsm_run(capsys, machine("sense", SENSE), "--world", "sim", "--scenario", scene)
    assert "scene.yaml:9:21: error[E200]: 'at' must be >= 0, not -5 (seconds into the run)" in err
    assert "scene.yaml:9:25: error[E200]: unknown key 'why'" in err
    scene.write_text(SCENE.replace("yaw: -90}", "yaw: -90, body: ful}") + "failures:\n  - {robot: r2, at: 5}\n")
    code, _, err = hfsm_run(capsys, machine("sense", SENSE), "--world", "sim", "--scenario", scene)
    assert code == 2 and "did you mean 'full'?" in err
    assert "no robot named" not in err  # a robot refused for its body is no unknown robot
