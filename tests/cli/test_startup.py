"""Commands that need no world start light: no simulator, no OpenCV, no numpy, no banner (issue 12.5).

Each command runs in a fresh interpreter, which then reports which heavy modules it imported.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("pybullet", "cv2", "numpy", "hfsm_sim", "hfsm_behaviours.approach", "hfsm_behaviours.carry")
PROBE = """
import json, sys
from {module} import main
code = main({argv!r})
heavy = sorted(m for m in {heavy!r} if m in sys.modules)
print("\\n" + json.dumps({{"code": code, "heavy": heavy}}))
"""

COMMANDS = {
    "check": ("hfsm.cli.run", ["examples/hello.yaml", "--check"]),
    "check the paper's machines": ("hfsm.cli.run", ["machines/move_furniture.yaml", "--check"]),
    "world none": ("hfsm.cli.run", ["examples/hello.yaml", "--world", "none", "--quiet"]),
    "list": ("hfsm.cli.run", ["--list"]),
    "test": ("hfsm.cli.test", ["tests/machines/elect_leader.test.yaml"]),
    "graph": ("hfsm.cli.graph", ["machines/move_table.yaml", "-o", "{tmp}", "--format", "dot"]),
}


def probe(module: str, argv: list[str]) -> tuple[dict[str, object], str, str]:
    code = PROBE.format(module=module, argv=argv, heavy=HEAVY)
    done = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120, check=False
    )
    *out, last = done.stdout.rstrip("\n").split("\n")
    return json.loads(last), "\n".join(out).strip(), done.stderr


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_world_free_commands_import_no_simulator(name: str, tmp_path: Path) -> None:
    module, argv = COMMANDS[name]
    report, _, err = probe(module, [a.format(tmp=tmp_path) for a in argv])
    passed = (0, 1) if name == "test" else (0,)  # hfsm-test: a failing case is not this test's concern
    assert report["code"] in passed and report["heavy"] == [], err
    assert "pybullet build time" not in err


def test_check_is_silent_but_for_its_verdict() -> None:
    report, out, err = probe("hfsm.cli.run", ["examples/hello.yaml", "--check"])
    assert report["code"] == 0 and out == ""
    assert err == "examples/hello.yaml: ok (1 machines checked)\n"
