"""pybullet's banner ("pybullet build time: ...", printed from C at its first import) never shows."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_importing_the_simulator_prints_nothing() -> None:
    done = subprocess.run([sys.executable, "-c", "import hfsm_sim.world; print('ready')"], cwd=ROOT,
                          capture_output=True, text=True, check=True)
    assert (done.stdout, done.stderr) == ("ready\n", "")


def test_a_sim_command_prints_no_banner(tmp_path: Path) -> None:
    hfsm_run = Path(sys.executable).parent / "hfsm-run"
    done = subprocess.run([str(hfsm_run), str(ROOT / "machines" / "move_furniture.yaml"), "--max-time", "0.05",
                           "--no-video", "--quiet", "--out", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 1 and "stopped at --max-time" in done.stderr
    assert "pybullet" not in done.stdout + done.stderr
