"""TARARC's held-back team scenarios (issue 9): sizes, rooms and failure times the bench never
runs, each of which must complete. Light robots in the simulator; every robot left ends `done`
with every group's task a success and one plan on every robot."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from helpers import ROOT, hfsm_run

TARARC = ROOT / "machines" / "tararc.yaml"

TWELVE = """  # 12 robots in rows in a 10 x 8 room, 4 targets, a member failing at 7.3 s
room: {width: 10.0, depth: 8.0}
tables: []
targets:
  - {id: a, x: 3.0, y: 2.2, difficulty: 0.35, priority: 2}
  - {id: b, x: 3.2, y: -2.0, difficulty: 0.8, priority: 1}
  - {id: c, x: 0.5, y: 0.3, difficulty: 0.5, priority: 4}
  - {id: d, x: -0.8, y: -2.6, difficulty: 0.2, priority: 3}
robots:
  r1: {x: -4.0, y: 1.2, body: light}
  r2: {x: -3.1, y: 1.2, body: light}
  r3: {x: -2.2, y: 1.2, body: light}
  r4: {x: -1.3, y: 1.2, body: light}
  r5: {x: -4.0, y: 0.2, body: light}
  r6: {x: -3.1, y: 0.2, body: light}
  r7: {x: -2.2, y: 0.2, body: light}
  r8: {x: -1.3, y: 0.2, body: light}
  r9: {x: -4.0, y: -0.8, body: light}
  r10: {x: -3.1, y: -0.8, body: light}
  r11: {x: -2.2, y: -0.8, body: light}
  r12: {x: -1.3, y: -0.8, body: light}
failures:
  - {robot: r6, at: 7.3, reason: held-back}
"""

SEVEN = """  # 7 robots scattered in a 9 x 7 room, 2 targets, r2 failing at 5.55 s
room: {width: 9.0, depth: 7.0}
tables: []
targets:
  - {id: east, x: 3.1, y: -1.4, difficulty: 0.65, priority: 1}
  - {id: north, x: -0.6, y: 2.3, difficulty: 0.25, priority: 2}
robots:
  r1: {x: -3.3, y: -2.1, body: light}
  r2: {x: -1.7, y: -0.4, body: light}
  r3: {x: -3.6, y: 0.9, body: light}
  r4: {x: -0.2, y: -2.5, body: light}
  r5: {x: -2.4, y: 2.2, body: light}
  r6: {x: 0.9, y: 0.3, body: light}
  r7: {x: -2.6, y: -1.2, body: light}
failures:
  - {robot: r2, at: 5.55, reason: held-back}
"""

SIXTEEN = """  # 16 robots at 0.8 m/s in a 14 x 10 room, 5 targets, r11 failing at 11.1 s
room: {width: 14.0, depth: 10.0}
tables: []
targets:
  - {id: t1, x: 5.0, y: 3.0, difficulty: 0.3, priority: 5}
  - {id: t2, x: 5.2, y: -3.1, difficulty: 0.9, priority: 1}
  - {id: t3, x: 1.5, y: 0.2, difficulty: 0.6, priority: 3}
  - {id: t4, x: 1.0, y: 3.6, difficulty: 0.45, priority: 2}
  - {id: t5, x: 1.2, y: -3.4, difficulty: 0.75, priority: 4}
robots:
  r1: {x: -5.5, y: -1.65, body: light, speed: 0.8}
  r2: {x: -4.5, y: -1.65, body: light, speed: 0.8}
  r3: {x: -3.5, y: -1.65, body: light, speed: 0.8}
  r4: {x: -2.5, y: -1.65, body: light, speed: 0.8}
  r5: {x: -5.5, y: -0.55, body: light, speed: 0.8}
  r6: {x: -4.5, y: -0.55, body: light, speed: 0.8}
  r7: {x: -3.5, y: -0.55, body: light, speed: 0.8}
  r8: {x: -2.5, y: -0.55, body: light, speed: 0.8}
  r9: {x: -5.5, y: 0.55, body: light, speed: 0.8}
  r10: {x: -4.5, y: 0.55, body: light, speed: 0.8}
  r11: {x: -3.5, y: 0.55, body: light, speed: 0.8}
  r12: {x: -2.5, y: 0.55, body: light, speed: 0.8}
  r13: {x: -5.5, y: 1.65, body: light, speed: 0.8}
  r14: {x: -4.5, y: 1.65, body: light, speed: 0.8}
  r15: {x: -3.5, y: 1.65, body: light, speed: 0.8}
  r16: {x: -2.5, y: 1.65, body: light, speed: 0.8}
failures:
  - {robot: r11, at: 11.1, reason: held-back}
"""

NINE = """  # 9 robots in a narrow 11 x 6 room, 3 targets (one 1 m from a wall), r4 failing while the team shares
room: {width: 11.0, depth: 6.0}
tables: []
targets:
  - {id: near, x: 0.4, y: 1.5, difficulty: 0.55, priority: 2}
  - {id: far, x: 4.2, y: -0.6, difficulty: 0.85, priority: 1}
  - {id: low, x: 1.8, y: -2.0, difficulty: 0.15, priority: 3}
robots:
  r1: {x: -4.2, y: -1.8, body: light}
  r2: {x: -3.0, y: -1.9, body: light}
  r3: {x: -4.4, y: -0.3, body: light}
  r4: {x: -3.1, y: 0.1, body: light}
  r5: {x: -1.9, y: -0.6, body: light}
  r6: {x: -4.1, y: 1.4, body: light}
  r7: {x: -2.8, y: 1.6, body: light}
  r8: {x: -1.6, y: 1.0, body: light}
  r9: {x: -1.2, y: 2.3, body: light}
failures:
  - {robot: r4, at: 0.1, reason: held-back}
"""

CASES = [("twelve", TWELVE, 0, 0.0), ("seven", SEVEN, 1, 0.0), ("seven_lossy", SEVEN, 2, 0.3),
         ("sixteen", SIXTEEN, 1, 0.0), ("nine", NINE, 0, 0.0)]


def run(capsys: pytest.CaptureFixture[str], tmp_path: Path, scenario: str, seed: int, loss: float
        ) -> dict[str, Any]:
    path = tmp_path / "scenario.yaml"
    path.write_text(scenario, encoding="utf-8")
    code, out, err = hfsm_run(capsys, TARARC, "--world", "sim", "--scenario", path, "--seed", seed,
                              "--radio-loss", loss, "--json", "--no-video", "--quiet", "--out", tmp_path)
    assert code == 0, err
    return dict(json.loads(out))


@pytest.mark.slow
@pytest.mark.parametrize(("name", "scenario", "seed", "loss"), CASES, ids=[c[0] for c in CASES])
def test_a_held_back_team_completes(capsys: pytest.CaptureFixture[str], tmp_path: Path, name: str,
                                    scenario: str, seed: int, loss: float) -> None:
    agents = run(capsys, tmp_path, scenario, seed, loss)["agents"]
    failed = [a for a, r in agents.items() if r.get("failed")]
    assert len(failed) == 1
    left = {a: r for a, r in agents.items() if a not in failed}
    assert {r["outcome"] for r in left.values()} == {"done"}
    plans = [r["outputs"]["plan"] for r in left.values()]
    assert all(p == plans[0] for p in plans)
    outcomes = [r["outputs"]["outcomes"] for r in left.values()]
    assert all(o == outcomes[0] for o in outcomes) and outcomes[0] and all(outcomes[0])
