"""The approach machines: checks, the election, and the whole approach in the six scenarios."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from approach_run import DATA, ROOT, approach_library, exit_time, registry, run_machine
from helpers import execute

from hfsm.load import load

MINE = ["move_furniture", "look_for_table", "elect_leader", "leader", "assistant",
        "wait_until_clear_way", "wait_until_leader_at_centre_of_table"]
SCENARIOS = ["opposite_long_side", "ahead_behind", "facing_away", "facing_table", "same_side",
             "opposite_short_side"]


@pytest.mark.parametrize("name", MINE)
def test_machine_passes_strict_checks(name: str, tmp_path: Path) -> None:
    top = approach_library(tmp_path).with_name(f"{name}.yaml")
    assert (ROOT / "machines" / top.name).exists()
    loaded = load([top], registry=registry())
    # the copies shadow the library's machines of the same names, by design of the copy (W406)
    assert [w.code for w in loaded.warnings if w.code != "W406"] == []


def election(machine: Callable[[str, str], Path], mine: str) -> Path:
    return machine("vote", f"""
        vars: {{role: ""}}
        outcomes: [done]
        outputs: {{role: "${{vars.role}}"}}
        states:
          elect:
            do: elect_leader
            with: {{distance: "${{{mine}}}"}}
            save: {{role: role}}
            on: {{elected: done, timeout: done}}
    """)


def test_the_closer_robot_leads(machine: Callable[[str, str], Path]) -> None:
    result, _ = execute(election(machine, "1.0 if agent.id == 'b' else 2.0"), agents=("a", "b"))
    roles = {n: a.outputs["role"] for n, a in result.agents.items()}
    assert roles == {"a": "assistant", "b": "leader"}


def test_a_tie_goes_to_the_lower_id(machine: Callable[[str, str], Path]) -> None:
    result, _ = execute(election(machine, "1.0 if agent.id == 'b' else 1.02"), agents=("a", "b"))
    roles = {n: a.outputs["role"] for n, a in result.agents.items()}
    assert roles == {"a": "leader", "b": "assistant"}


def approach(tmp_path: Path, scenario: str, seed: int) -> None:
    top = approach_library(tmp_path, DATA / "move_table_lift_check.yaml")
    result, records, judged = run_machine(top, scenario, seed)
    assert result.error is None
    assert {n: a.outcome for n, a in result.agents.items()} == {"r1": "at_wall", "r2": "at_wall"}
    assert sorted(a.outputs["role"] for a in result.agents.values()) == ["assistant", "leader"]
    places = judged["placements"]
    assert places["r1"].side == -places["r2"].side != 0
    assert all(abs(p.along) < 0.04 and 0.03 < p.depth < 0.1 for p in places.values())
    assert judged["score"]["robot_collisions"] == 0
    assert judged["score"]["robot_table_collisions"] == 0
    assert all((exit_time(records, n, "go_to_the_lifting_point") or 1e9) < 240 for n in result.agents)


def test_the_approach_from_opposite_long_sides(tmp_path: Path) -> None:
    approach(tmp_path, "opposite_long_side", 0)


@pytest.mark.parametrize("scenario", SCENARIOS[1:])
@pytest.mark.parametrize("seed", [0, 1])
def test_the_approach_from_every_start(tmp_path: Path, scenario: str, seed: int) -> None:
    approach(tmp_path, scenario, seed)
