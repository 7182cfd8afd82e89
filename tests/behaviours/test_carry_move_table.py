"""The carry machines: the lift handshake (Figure 8) and Move table end to end (Figure 3)."""

from __future__ import annotations

import random
import subprocess
import sys
from pathlib import Path

import pytest
from carry_scene import DATA, ROOT, at_table, machine_file, run_in_scene

MACHINES = [ROOT / "machines" / "move_table.yaml", ROOT / "machines" / "synchronised_lift_table.yaml",
            DATA / "carry_only.yaml"]


@pytest.mark.parametrize("path", MACHINES, ids=lambda p: p.name)
def test_machine_passes_strict_checks(path: Path) -> None:
    run = subprocess.run([sys.executable, "-m", "hfsm.cli.run", str(path), "--check", "--strict"],
                         capture_output=True, text=True, check=False, cwd=ROOT)
    assert run.returncode == 0, run.stdout + run.stderr


def test_synchronised_lift_agrees_the_travel_and_lifts_together(tmp_path: Path) -> None:
    top = machine_file(tmp_path, """
        vars: {direction: "", steps: 0}
        outcomes: [done, failure, timeout]
        outputs: {direction: "${vars.direction}", steps: "${vars.steps}"}
        timer: 60
        states:
          lift:
            do: synchronised_lift_table
            with: {role: "${'leader' if agent.id == 'r1' else 'assistant'}", direction: right,
                   steps: 4}
            save: {direction: direction, steps: steps}
            on: {lifted: land, at_wall: failure, failure: failure, timeout: failure}
          land: {do: land_table, on: {landed: done, failure: failure}}
    """)
    run = run_in_scene(top, at_table())
    assert run.outputs("r1") == {"direction": "right", "steps": 4}
    assert run.outputs("r2") == {"direction": "left", "steps": 4}  # facing each other
    lifts = [r for r in run.records if r["kind"] == "exit" and r["path"][-1] == "lift"
             and len(r["path"]) == 3]
    assert len(lifts) == 2 and abs(lifts[0]["t"] - lifts[1]["t"]) <= 0.3
    assert not run.score["dropped"]


@pytest.mark.parametrize("scenario", ["at_table", "at_table_offset"])
def test_move_table_carries_the_table_to_the_wall(scenario: str) -> None:
    run = run_in_scene(DATA / "carry_only.yaml", str(DATA / f"{scenario}.yaml"))
    assert (run.outcome("r1"), run.outcome("r2")) == ("at_wall", "at_wall")
    assert run.score["success"], run.score
    assert run.score["robot_collisions"] == 0 and not run.score["dropped"]
    assert run.result.agents["r2"].time < 150.0  # 1.5 m at 0.05 m/s, in cycles of 10 steps
    assert run.table[0] > 1.9  # toward +x, the nearer wall


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(4))
def test_move_table_from_jittered_starts(seed: int) -> None:
    """Robots off the middle by up to 10 cm, off grip depth by 2 cm, turned up to 8 degrees,
    the table nearer one wall or the other; a lossless radio with 0.1-0.3 s latency."""
    rng = random.Random(seed)

    def offset() -> tuple[float, float, float]:
        return (rng.uniform(-0.1, 0.1), rng.uniform(-0.02, 0.02), rng.uniform(-8.0, 8.0))

    table_x = rng.choice([-1.0, -0.5, 0.5, 1.0])
    run = run_in_scene(DATA / "carry_only.yaml", at_table(offset(), offset(), table_x=table_x),
                       seed=seed, radio_latency=rng.uniform(0.1, 0.3))
    assert run.score["success"], (seed, run.score)
    assert (run.outcome("r1"), run.outcome("r2")) == ("at_wall", "at_wall")
