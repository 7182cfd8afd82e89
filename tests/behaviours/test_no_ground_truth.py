"""Robots behave on what they sense: hfsm_behaviours/ and machines/ never reach the simulator's ground truth."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ADAPTERS = {"world.py", "simworld.py", "trial.py"}  # the world seam: it holds the World to step and score it
FORBIDDEN_MODULES = (
    "pybullet",
    "hfsm_sim.world",
    "hfsm_sim.truth",
    "hfsm_sim.scorer",
    "hfsm_sim.body",
    "hfsm_sim.lifting",
    "hfsm_sim.room",
)
FORBIDDEN_NAMES = {"truth", "score", "getBasePositionAndOrientation", "client", "scenario"}


def behaviour_files() -> list[Path]:
    return [p for p in sorted((ROOT / "hfsm_behaviours").rglob("*.py")) if p.name not in ADAPTERS]


@pytest.mark.parametrize("path", behaviour_files(), ids=lambda p: str(p.relative_to(ROOT)))
def test_no_ground_truth_in_behaviours(path: Path) -> None:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import | ast.ImportFrom):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
            assert not any(n.startswith(FORBIDDEN_MODULES) for n in names), f"{path}: imports {names}"
        if isinstance(node, ast.Attribute):
            assert node.attr not in FORBIDDEN_NAMES, f"{path}:{node.lineno}: reads .{node.attr}"
            own = isinstance(node.value, ast.Name) and node.value.id in ("self", "cls")
            assert own or not (node.attr.startswith("_") and not node.attr.startswith("__")), (
                f"{path}:{node.lineno}: reaches private .{node.attr}"
            )


def test_machines_name_no_simulator_internals() -> None:
    for path in sorted((ROOT / "machines").glob("*.yaml")):
        text = path.read_text(encoding="utf-8")
        assert "truth" not in text and "pybullet" not in text, path
