"""TARARC's machines in the simulator: light robots share, group, move, help and remember."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from helpers import ROOT, hfsm_run

TARARC = ROOT / "machines" / "tararc.yaml"
TWO_TARGETS = """
room: {width: 10.0, depth: 8.0}
tables: []
targets:
  - {id: north, x: 0.0, y: 2.5, difficulty: 0.4, priority: 1}
  - {id: south, x: 0.5, y: -2.5, difficulty: 0.7, priority: 2}
"""
TEAM = TWO_TARGETS + """
robots:
  r1: {x: -2.0, y: 0.5, body: light}
  r2: {x: -1.0, y: 0.5, body: light}
  r3: {x: 0.0, y: 0.5, body: light}
  r4: {x: -2.0, y: -0.5, body: light}
  r5: {x: -1.0, y: -0.5, body: light}
  r6: {x: 0.0, y: -0.5, body: light}
failures:
  - {robot: r1, at: 4.0, reason: fell}
"""


def run(capsys: pytest.CaptureFixture[str], tmp_path: Path, *flags: object) -> dict[str, Any]:
    code, out, err = hfsm_run(capsys, TARARC, "--world", "sim", "--json", "--no-video", "--out", tmp_path,
                              "--quiet", *flags)
    assert code == 0, err
    return dict(json.loads(out))


def decided(result: dict[str, Any]) -> dict[str, Any]:
    keys = ("role", "agent", "task", "lost", "outcomes")
    return {a: (r["outcome"], {k: r["outputs"].get(k) for k in keys}) for a, r in result["agents"].items()}


@pytest.mark.slow
def test_ten_light_robots_allocate_three_targets_and_remember(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    history = tmp_path / "history.json"
    result = run(capsys, tmp_path, "--scenario", "alloc_3_tasks", "--history", history)
    agents = result["agents"]
    assert {a["outcome"] for a in agents.values()} == {"done"}
    plans = [a["outputs"]["plan"] for a in agents.values()]
    assert all(p == plans[0] for p in plans)
    assert sorted(g["task"]["id"] for g in plans[0]["groups"]) == ["t1", "t2", "t3"]
    assert agents["r1"]["outputs"]["outcomes"] == [True, True, True]
    assert '"n_s": 1' in history.read_text(encoding="utf-8")


@pytest.mark.slow
def test_the_agent_falls_mid_move_and_a_member_takes_over(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scenario = tmp_path / "team.yaml"
    scenario.write_text(TEAM, encoding="utf-8")
    clean = run(capsys, tmp_path, "--scenario", scenario)
    agents = clean["agents"]
    assert agents["r1"]["failed"] == "fell"
    first = agents["r2"]["outputs"]["first"]
    assert first["groups"][0]["agent"] == "r1"  # it was an agent when it fell
    for name in ("r2", "r3", "r4", "r5", "r6"):
        assert agents[name]["outcome"] == "done"
        assert agents[name]["outputs"]["lost"] == ["r1"]
        assert agents[name]["outputs"]["outcomes"] == [True, True]
    new = agents["r2"]["outputs"]["plan"]["groups"][0]["agent"]
    assert new in ("r2", "r3") and agents[new]["outputs"]["role"] == "agent"
    lossy = run(capsys, tmp_path, "--scenario", scenario, "--radio-loss", "0.3")
    assert decided(lossy) == decided(clean)


LENDING = TWO_TARGETS + """
robots:
  r1: {x: -2.0, y: 0.5, body: light}
  r2: {x: -1.0, y: 0.5, body: light}
  r3: {x: -2.0, y: -0.5, body: light}
  r4: {x: -1.0, y: -0.5, body: light}
  r5: {x: 0.0, y: -0.5, body: light}
failures:
  - {robot: r2, at: 4.0, reason: fell}
"""


@pytest.mark.slow
def test_a_member_falls_and_the_nearest_group_lends_one(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """7b: north's group (r1, r2) loses r2; south's (r3, r4, r5) lends r4, the nearest r1."""
    scenario = tmp_path / "lending.yaml"
    scenario.write_text(LENDING, encoding="utf-8")
    agents = run(capsys, tmp_path, "--scenario", scenario)["agents"]
    assert agents["r2"]["failed"] == "fell"
    groups = [g["members"] for g in agents["r1"]["outputs"]["plan"]["groups"]]
    assert groups == [["r1", "r4"], ["r3", "r5"]]
    assert all(agents[r]["outputs"]["outcomes"] == [True, True] for r in ("r1", "r3", "r4", "r5"))


@pytest.mark.slow
def test_a_robot_failing_while_the_team_shares_goes_without_it(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """r6 fails (`--fail`) before it says its state: the others give it up after `silence` and the
    five left make the plan, move and complete both targets instead of waiting for it until the
    exchange's limit."""
    scenario = tmp_path / "team.yaml"
    scenario.write_text(TEAM.split("failures:")[0], encoding="utf-8")
    agents = run(capsys, tmp_path, "--scenario", scenario, "--fail", "r6@0.05")["agents"]
    assert agents["r6"]["failed"]
    plan = agents["r1"]["outputs"]["plan"]
    assert sorted(plan["robots"]) == ["r1", "r2", "r3", "r4", "r5"]
    for name in ("r1", "r2", "r3", "r4", "r5"):
        assert agents[name]["outcome"] == "done"
        assert agents[name]["outputs"]["outcomes"] == [True, True]
