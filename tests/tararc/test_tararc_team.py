"""TARARC's machines with whole teams: the same decisions at 30 % loss, and the history across runs."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest
from tararc_runs import case, decisions, run_plan

from hfsm.runtime.run import RunResult
from hfsm.testing.model import FailAt
from hfsm_behaviours.tararc.history import History, Record
from hfsm_behaviours.tararc.history_file import dumps, load, save

KEYS = ("role", "agent", "task", "lost", "outcomes")
TEAM_CASES = [
    "four_robots_two_tasks",
    "six_robots_three_tasks",
    "the_agent_fails_mid_move",
    "a_member_fails_and_the_nearest_group_lends",
    "an_agent_low_on_energy_hands_over",
]


@pytest.mark.parametrize("name", TEAM_CASES)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_thirty_percent_loss_gives_the_same_team_later(name: str, seed: int) -> None:
    plan = case("tararc.test.yaml", name)
    clean, none_lost = run_plan(plan)
    lossy, lost = run_plan(plan, loss=0.3, seed=seed)
    assert none_lost == 0 and lost > 0
    assert decisions(lossy, KEYS) == decisions(clean, KEYS)
    # Later, but for failures: silence counts from the last heartbeat heard, which losses make
    # older, so a lossy radio may notice a silent robot sooner.
    if not plan.fail:
        for agent, result in clean.agents.items():
            assert lossy.agents[agent].time >= result.time


def one_plan(result: RunResult) -> dict[str, Any]:
    """The plan every robot that finished holds: they must all hold the same."""
    plans = [a.outputs["plan"] for a in result.agents.values() if a.outcome == "done"]
    assert plans and all(p == plans[0] for p in plans)
    return plans[0]


@pytest.mark.parametrize("name", [*TEAM_CASES, "a_group_waits_for_its_slowest_member"])
def test_every_robot_holds_the_same_plan(name: str) -> None:
    plan = case("tararc.test.yaml", name)
    assert one_plan(run_plan(plan)[0]) == one_plan(run_plan(plan, loss=0.3, seed=5)[0])


def test_a_robot_says_the_state_it_computes_with() -> None:
    """Its battery drains while the team shares: what it said is still what it computes with."""
    plan = case("tararc.test.yaml", "four_robots_two_tasks")
    drain = plan.inputs[0][0].model_copy(update={"at": 0.1, "in_": {"battery": 0.2}})
    result, _ = run_plan(replace(plan, inputs=[*plan.inputs, (drain, plan.inputs[0][1])]))
    assert one_plan(result)["robots"]["r0"]["energy"] == 1.0


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_the_exchange_survives_loss(seed: int) -> None:
    plan = case("tararc_share.test.yaml", "three_robots_hear_each_other")
    clean, _ = run_plan(plan)
    lossy, lost = run_plan(plan, loss=0.3, seed=seed)
    assert lost > 0
    assert decisions(lossy, ("heard",)) == decisions(clean, ("heard",))


def test_the_history_round_trips_across_two_runs(tmp_path: Path) -> None:
    history = tmp_path / "history.json"
    plan = case("tararc.test.yaml", "four_robots_two_tasks")
    run_plan(plan, history=str(history))
    first = load(history)
    assert first.pairs == {("r0", "r1"): Record(1, 0), ("r2", "r3"): Record(1, 0)}
    assert first.robots == {r: Record(1, 0) for r in ("r0", "r1", "r2", "r3")}
    run_plan(plan, history=str(history))
    second = load(history)
    assert second.pairs == {("r0", "r1"): Record(2, 0), ("r2", "r3"): Record(2, 0)}
    assert set(second.beliefs) == {"r0", "r1", "r2", "r3"}
    # every robot wrote the same update: the file is the one a single writer gives
    assert dumps(load(history)) == history.read_text(encoding="utf-8")


def test_a_lost_robot_fails_its_collaborations(tmp_path: Path) -> None:
    history = tmp_path / "history.json"
    run_plan(case("tararc.test.yaml", "the_agent_fails_mid_move"), history=str(history))
    after = load(history)
    assert after.robot_record("r0") == Record(0, 1)
    assert after.pair_record("r0", "r1") == Record(0, 1)
    assert after.robot_record("r1") == Record(1, 0)  # it finished east as the new agent
    assert after.beliefs["r1"] > after.beliefs["r0"]


def test_history_regroups_the_team(tmp_path: Path) -> None:
    """Relevance earned together (r0-r2, r1-r3) outweighs the ids: the groups follow the history."""
    history = tmp_path / "history.json"
    text = {"version": 1,
            "pairs": [{"robots": ["r0", "r2"], "n_s": 3, "n_f": 0}, {"robots": ["r1", "r3"], "n_s": 2, "n_f": 1}],
            "robots": [{"id": "r9", "n_s": 1, "n_f": 0}]}
    history.write_text(json.dumps(text), encoding="utf-8")
    result, _ = run_plan(case("tararc.test.yaml", "four_robots_two_tasks"), history=str(history))
    groups = [g["members"] for g in result.agents["r0"].outputs["plan"]["groups"]]
    assert sorted(map(sorted, groups)) == [["r0", "r2"], ["r1", "r3"]]
    after = load(history)
    assert after.pair_record("r0", "r2") == Record(4, 0)
    assert after.robot_record("r9") == Record(1, 0)  # robots of other teams are kept


def test_a_run_without_a_history_writes_nothing(tmp_path: Path) -> None:
    run_plan(case("tararc.test.yaml", "four_robots_two_tasks"))
    assert list(tmp_path.iterdir()) == []


def test_save_replaces_the_file_and_leaves_no_temporary(tmp_path: Path) -> None:
    path = tmp_path / "h.json"
    path.write_text("old", encoding="utf-8")
    save(path, History({("a", "b"): Record(1, 0)}))
    assert [p.name for p in tmp_path.iterdir()] == ["h.json"]
    assert load(path).pair_record("a", "b") == Record(1, 0)


class Exits:
    """A trace sink keeping when each agent left each top-level state of tararc."""

    def __init__(self) -> None:
        self.left: dict[tuple[str, str], float] = {}

    def write(self, record: dict[str, Any]) -> None:
        if record["kind"] == "exit" and len(record["path"]) == 2:
            self.left.setdefault((record["agent"], record["path"][1]), record["t"])

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


@pytest.mark.parametrize("at", [0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.8])
@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4])
def test_a_robot_failing_mid_exchange_at_thirty_percent_loss_splits_nobody(at: float, seed: int) -> None:
    """r3 fails while the team meets or shares its states, on a radio losing 30 % of messages and
    barrier notices: every survivor ends `done` with the same plan (r3 in it for all or for
    none), and none waits at `meet` longer than `silence` (5 s)."""
    plan = case("tararc.test.yaml", "four_robots_two_tasks")
    plan = replace(plan, fail=[FailAt(agent="r3", at=at)])
    exits = Exits()
    result, lost = run_plan(plan, loss=0.3, seed=seed, trace=exits)
    assert lost > 0
    survivors = [a for a in result.agents if a != "r3"]
    assert all(result.agents[a].outcome == "done" for a in survivors)
    first = {a: result.agents[a].outputs["first"] for a in survivors}
    assert all(f == first[survivors[0]] for f in first.values()), first
    one_plan(result)
    assert all(exits.left[a, "meet"] <= 5.0 + 0.1 for a in survivors if (a, "meet") in exits.left)
