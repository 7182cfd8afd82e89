"""Figure 8 world-free: four allocations over a scripted history, one group failing wholly in the third."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.tararc.history import History, p_term  # noqa: E402
from hfsm_behaviours.tararc.outcome import record_team  # noqa: E402
from hfsm_behaviours.tararc.plan import after_losses, history_of, make_plan, record_of  # noqa: E402
from tools.tararc.ability import chain, failing_group, follow, group_abilities, match, paper_names  # noqa: E402
from tools.tararc.report import ability  # noqa: E402
from tools.tararc.scenes import scene  # noqa: E402


def allocations(fail_in: int, count: int = 4) -> list[dict[str, Any]]:
    """The bench's Figure 8 chain with the world left out: every robot where the scene puts it, full,
    each allocation made by `make_plan` from the history, then the history updated by `record_team`;
    in allocation `fail_in` every robot of the group `failing_group` picks is lost."""
    sc = scene(priorities=(3, 2, 1))
    history = History()
    runs = []
    for k in range(1, count + 1):
        states = {r: {"x": p["x"], "y": p["y"], "energy": 1.0, "record": record_of(history, r)}
                  for r, p in sc["robots"].items()}
        first = make_plan(states, sc["targets"])
        groups = group_abilities(first)
        lost = groups[failing_group(groups)]["members"] if k == fail_in else []
        last = after_losses(first, lost, 2)
        outcomes = [bool(g["members"]) for g in last["groups"]]
        history = record_team(history_of(states), first, last, lost, outcomes)
        runs.append({"groups": groups, "failed": dict.fromkeys(lost, 1.0), "outcomes": outcomes,
                     "p": {g["agent"]: p_term(history, g["agent"]) for g in groups}})
    return runs


def test_a_group_failing_its_third_task_drops_and_gets_the_easiest_in_the_fourth() -> None:
    runs = chain(allocations(fail_in=3))
    before, after = runs[2][0], runs[3][0]
    assert not before["ok"] and after["ok"]
    assert after["F"] < before["F"] and after["B"] < before["B"]
    assert (before["difficulty"], after["difficulty"]) == (0.6, 0.3)
    assert all(alloc[2]["difficulty"] == 0.9 for alloc in runs)  # the paper's group 2: always the hardest
    assert runs[3][1]["difficulty"] == 0.6  # group 1 moves up to the second hardest


def test_the_failed_group_recovers_after_a_success() -> None:
    runs = allocations(fail_in=3, count=5)
    agent = chain(runs)[2][0]["agent"]
    # P_j^beta of its agent after each allocation: 1 success, 2, then 2 of 3 (beta 1/2), then 3 of 4 (beta 1/3)
    assert [round(run["p"].get(agent, -1), 3) for run in runs[:4]] == [1.0, 1.0, 0.816, 0.909]
    fifth = chain(runs)[4][0]  # a fifth allocation: the group wins the second hardest task back
    assert fifth["difficulty"] == 0.6 and fifth["F"] > chain(runs)[3][0]["F"] and fifth["agent"] != agent


def test_without_the_failure_nothing_drops() -> None:
    runs = allocations(fail_in=0)
    assert all(all(run["outcomes"]) for run in runs)
    lineages = follow([[g["members"] for g in run["groups"]] for run in runs])
    by_lineage = [dict(zip(lins, run["groups"], strict=True))
                  for lins, run in zip(lineages, runs, strict=True)]
    for lin in by_lineage[0]:
        f = [alloc[lin]["F"] for alloc in by_lineage]
        assert f[1] > f[0]  # a first success raises F; the tasks keep their groups
    def won(alloc: dict[int, dict[str, Any]]) -> dict[int, float]:
        return {lin: g["difficulty"] for lin, g in alloc.items()}

    assert won(by_lineage[3]) == won(by_lineage[2])


def test_b_is_the_auctions_at_the_agents_place() -> None:
    sc = scene()
    history = History()
    states = {r: {"x": p["x"], "y": p["y"], "energy": 1.0, "record": record_of(history, r)}
              for r, p in sc["robots"].items()}
    first = make_plan(states, sc["targets"])
    first["groups"][0]["members"].reverse()  # the agent now at place j_ord = n-1: F is divided by 1 + k5 (n-1)
    g = first["groups"][0]
    again = group_abilities(first)[0]
    at_zero = group_abilities(make_plan(states, sc["targets"]))[0]
    assert again["F"] == pytest.approx(at_zero["F"] / (1 + 0.2 * (len(g["members"]) - 1)), abs=1e-4)


def test_groups_are_followed_by_their_members() -> None:
    assert match([["a", "b"], ["c", "d"]], [["c", "d", "e"], ["a", "b"]]) == (1, 0)
    assert match([["a"], ["b"]], [["c"], ["d"]]) == (0, 1)  # nobody kept: the first matching
    assert follow([[["a", "b"], ["c"]], [["c"], ["a", "b"]], [["a", "c"], ["b"]]]) == [[0, 1], [1, 0], [1, 0]]
    with pytest.raises(ValueError, match="2 groups before, 1 now"):
        match([["a"], ["b"]], [["a", "b"]])
    assert paper_names([[0, 1, 2]], [[0.6, 0.3, 0.9]], failed=0) == {0: 0, 1: 1, 2: 2}
    assert paper_names([[0, 1, 2]], [[0.9, 0.3, 0.6]], failed=None) == {1: 0, 2: 1, 0: 2}


def test_the_failing_group_won_the_second_hardest_task() -> None:
    assert failing_group([{"difficulty": 0.3}, {"difficulty": 0.9}, {"difficulty": 0.6}]) == 2
    assert failing_group([{"difficulty": 0.3}]) == 0


def test_the_report_counts_the_papers_claims(tmp_path: Path) -> None:
    results = [{"experiment": "ability", "x": 0, "seed": 1, "runs": allocations(fail_in=3)}]
    text = "\n".join(ability(results, tmp_path))
    assert "group 2 won the hardest task in 4 of 4 allocations" in text
    assert "task 0.6 → 0.3 (the easiest)" in text
    assert "**failed**" in text and (tmp_path / "fig8_ability.png").exists()
