"""Team scenarios through hfsm-run --world sim: light robots driven by go_to, scenario errors at
their positions, failures by a seeded rate, a 16-humanoid run, and eq. 5 as TARARC computes it."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest
from helpers import hfsm_run

from hfsm_behaviours.tararc.formulas import EnergyModel, energy
from hfsm_sim.battery import Battery
from hfsm_sim.specs import Eq5Battery

Machine = Callable[[str, str], Path]

DRIVE = """
outcomes: [done, late]
vars: {pose: {}}
outputs: {pose: "${vars.pose}"}
states:
  go:
    do: go_to
    with: {x: 1.0, y: 0.0, relative: true, tolerance: 0.05}
    on: {arrived: read, timeout: late}
  read: {do: set, with: {pose: "${in.pose}"}, on: {done: done}}
"""
PAUSE = "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 3}, on: {done: done}}\n"
LIGHT_TEAM = """
room: {width: 8.0, depth: 8.0}
tables: []
robots:
  r1: {x: -2.0, y: 0.0, body: light}
  r2: {x: -1.0, y: 0.0, body: light}
  r3: {x: 0.0, y: 0.0, body: light}
  r4: {x: 1.0, y: 0.0, body: light}
  r5: {x: 2.0, y: 0.0, body: light}
  r6: {x: 3.0, y: 0.0, body: light}
failures:
  - {rate: 20.0, robots: [r1, r2, r3, r4, r5], reason: broke}
"""


def test_light_robots_drive_where_go_to_sends_them(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    argv = (machine("drive", DRIVE), "--world", "sim", "--scenario", "alloc_3_tasks", "--json", "--no-video",
            "--out", tmp_path, "--quiet")
    code, out, err = hfsm_run(capsys, *argv)
    assert code == 0, err
    agents = json.loads(out)["agents"]
    assert len(agents) == 10 and {a["outcome"] for a in agents.values()} == {"done"}
    assert agents["r1"]["outputs"]["pose"]["x"] == pytest.approx(-3.5 + 1.0, abs=0.05)  # room frame


def test_team_scenario_errors_are_at_their_positions(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scene = tmp_path / "scene.yaml"
    scene.write_text(
        "tables:\n"
        "  - {x: 1.0, difficulty: 1.5}\n"
        "targets:\n"
        "  - {id: t1, x: 1.0, y: 1.0, priorty: 2}\n"
        "robots:\n"
        "  r1: {x: 0.0, y: 1.5, body: wheels}\n"
        "failures:\n"
        "  - {rate: 1.0, robots: [r1], why: x}\n"
    )
    code, _, err = hfsm_run(capsys, machine("pause", PAUSE), "--world", "sim", "--scenario", scene)
    assert code == 2
    assert (
        "scene.yaml:2:26: error[E200]: 'difficulty' must be > 0 and < 1, not 1.5 "
        "(TARARC's d_t, in the open interval (0, 1))"
    ) in err
    assert "scene.yaml:4:30: error[E200]: unknown key 'priorty'; did you mean 'priority'?" in err
    assert "scene.yaml:6:30: error[E200]: 'body': input should be 'full' or 'light', not 'wheels'" in err
    assert "scene.yaml:8:31: error[E200]: unknown key 'why' (allowed: rate, reason, robots)" in err
    assert "Traceback" not in err


def failures_of(capsys: pytest.CaptureFixture[str], pause: Path, scene: Path, out: Path, seed: int
                ) -> tuple[dict[str, object], bytes]:
    argv = (pause, "--world", "sim", "--scenario", scene, "--json", "--no-video", "--out", out, "--seed", seed,
            "--quiet")
    code, stdout, err = hfsm_run(capsys, *argv)
    assert code == 0, err  # r6, not at risk, ends: the run does (every agent failing would exit 1)
    agents = json.loads(stdout)["agents"]
    return {n: (a["time"], a.get("failed")) for n, a in agents.items()}, (out / f"scene-seed{seed}.jsonl").read_bytes()


def test_failures_by_rate_are_the_same_for_a_seed(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scene = tmp_path / "scene.yaml"
    scene.write_text(LIGHT_TEAM)
    pause = machine("pause", PAUSE)
    first, trace = failures_of(capsys, pause, scene, tmp_path / "a", 3)
    again, same = failures_of(capsys, pause, scene, tmp_path / "b", 3)
    other, _ = failures_of(capsys, pause, scene, tmp_path / "c", 4)
    assert (first, trace) == (again, same)
    assert first != other
    assert first["r6"] == (3.0, None)  # not at risk
    failed = [n for n, (_, why) in first.items() if why == "broke"]
    assert failed  # 20 a minute over 3 s: a robot survives with probability e^-1
    records = [json.loads(line) for line in trace.splitlines()]
    for name in failed:
        own = [r for r in records if r["agent"] == name]
        down = next(r for r in own if r["kind"] == "failed")
        assert down["reason"] == "broke" and down["t"] == first[name][0]  # type: ignore[index]
        assert {r["kind"] for r in own if r["t"] > down["t"]} == set()


def test_the_sims_eq5_battery_is_tararcs_energy() -> None:
    spec = Eq5Battery(model="eq5", w_tim=0.5, w_dist=0.3, w_sped=0.2, m=-0.4, n=-0.7, t=-1.2)
    battery = Battery(spec)
    battery.drain(10.0, 6.0, from_start=4.0, read=12)
    model = EnergyModel(w_tim=0.5, w_dist=0.3, w_sped=0.2, m=-0.4, n=-0.7, t=-1.2)
    assert battery.level == pytest.approx(energy(12, 4.0, 0.6, model), rel=1e-12)


@pytest.mark.slow
def test_sixteen_humanoids_run_headless(machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path
                                        ) -> None:
    argv = (machine("pause", PAUSE), "--world", "sim", "--scenario", "team_16", "--json", "--no-video",
            "--out", tmp_path, "--quiet")
    code, out, err = hfsm_run(capsys, *argv)
    assert code == 0, err
    result = json.loads(out)
    assert len(result["agents"]) == 16 and {a["outcome"] for a in result["agents"].values()} == {"done"}
    assert result["score"]["robot_collisions"] == 0
    poses = [json.loads(line) for line in (tmp_path / "team_16-seed0.jsonl").read_text().splitlines()]
    last = [r for r in poses if r["kind"] == "pose"][-1]
    assert len(last["robots"]) == 16 and len(last["tables"]) == 8
