"""The team's plan as data: made from broadcast states, redone after losses, and the run's record."""

from __future__ import annotations

import itertools
import math
from typing import Any

import pytest

from hfsm_behaviours.tararc.history import History, Record
from hfsm_behaviours.tararc.outcome import group_outcomes, merge_into, record_team
from hfsm_behaviours.tararc.plan import after_losses, history_of, key_of, make_plan, record_of, role_of

TASKS = [{"id": "east", "x": 6, "y": 0, "difficulty": 0.5, "priority": 1},
         {"id": "west", "x": -6, "y": 0, "difficulty": 0.8, "priority": 2}]
PLACES = {"r0": (1, 0), "r1": (2, 0), "r2": (-1, 0), "r3": (-1, 1), "r4": (-2, -1)}


NO_HISTORY = History()


def states(history: History = NO_HISTORY) -> dict[str, dict[str, Any]]:
    return {r: {"x": x, "y": y, "energy": 1.0 - 0.1 * i, "record": record_of(history, r)}
            for i, (r, (x, y)) in enumerate(PLACES.items())}


def test_what_robots_say_of_the_history_gives_it_back() -> None:
    h = History({("r0", "r1"): Record(2, 1), ("r1", "r4"): Record(0, 3)}, {"r1": Record(1, 1)}, {"r1": 0.4})
    assert record_of(h, "r1") == {"n_s": 1, "n_f": 1, "belief": 0.4, "pairs": {"r0": [2, 1], "r4": [0, 3]}}
    assert history_of(states(h)) == h


def test_the_plan_groups_elects_and_allocates() -> None:
    plan = make_plan(states(), TASKS)
    assert [(g["agent"], g["members"], g["task"]["id"]) for g in plan["groups"]] == [
        ("r0", ["r0", "r1"], "east"), ("r2", ["r2", "r3", "r4"], "west")]
    assert plan["robots"]["r3"] == {"x": -1.0, "y": 1.0, "energy": pytest.approx(0.7)}


def test_a_lost_agent_hands_over_to_the_highest_belief() -> None:
    plan = make_plan(states(), TASKS)
    after = after_losses(plan, ["r2"], n_thres=2)
    best = max(["r3", "r4"], key=lambda r: plan["beliefs"][r])
    assert after["groups"][1] == {"agent": best, "members": ["r3", "r4"], "task": plan["groups"][1]["task"]}
    assert after["groups"][0] == plan["groups"][0]


def test_a_short_group_borrows_from_the_nearest_group() -> None:
    plan = make_plan(states(), TASKS)
    after = after_losses(plan, ["r1"], n_thres=2)
    assert after["groups"][0]["members"] == ["r0", "r3"]  # r3 is nearer r0 than r4 is
    assert after["groups"][1]["members"] == ["r2", "r4"]


def test_a_group_with_no_robot_left_keeps_its_task() -> None:
    after = after_losses(make_plan(states(), TASKS), ["r0", "r1"], n_thres=2)
    east = {"id": "east", "x": 6.0, "y": 0.0, "difficulty": 0.5}
    assert after["groups"][0] == {"agent": None, "members": [], "task": east}
    assert group_outcomes(after, {"r2": True, "r3": True, "r4": True}) == [False, True]


def test_the_order_losses_are_heard_in_does_not_matter() -> None:
    plan = make_plan(states(), TASKS)
    lost = ["r1", "r2", "r4"]
    plans = [after_losses(plan, list(p), 2) for p in itertools.permutations(lost)]
    assert all(p == plans[0] for p in plans)
    assert len({key_of(list(p)) for p in itertools.permutations(lost)}) == 1
    assert key_of([]) == "k0" and key_of(["r1"]) != key_of(["r2"])


def test_roles_place_members_by_where_they_stand() -> None:
    plan = make_plan(states(), TASKS)
    agent = role_of(plan, "r2", [], spacing=1.0)
    member = role_of(plan, "r4", [], spacing=1.0)
    assert agent is not None and member is not None
    assert agent["role"] == "agent" and agent["slot"] == {"x": -6.0, "y": 0.0}
    assert agent["form"] == {"x": -1.0, "y": 0.0}  # the agent forms up where it stands
    assert agent["mates"] == ["r3", "r4"] and agent["others"] == ["r0", "r1", "r3", "r4"]
    # r4 stands at (-2, -1), south-west of its agent r2 (-1, 0): its place is on that side, 1 m off
    assert math.dist((member["form"]["x"], member["form"]["y"]), (-1, 0)) == pytest.approx(1.0)
    assert member["form"]["x"] < -1.5 and member["form"]["y"] < -0.5
    # round the task (-6, 0), coming from the east: r3 and r4 either side of the way in
    slots = [role_of(plan, r, [], 1.0)["slot"] for r in ("r3", "r4")]  # type: ignore[index]
    assert all(math.dist((s["x"], s["y"]), (-6, 0)) == pytest.approx(1.0) for s in slots)
    assert sorted(s["y"] > 0 for s in slots) == [False, True] and all(s["x"] > -6 - 1e-9 for s in slots)
    assert role_of(after_losses(plan, ["r4"], 2), "r4", ["r4"], 1.0) is None


def test_the_run_is_recorded_with_its_losses() -> None:
    first = make_plan(states(), TASKS)
    last = after_losses(first, ["r1"], 2)
    after = record_team(History(), first, last, ["r1"], [True, False])
    assert after.pair_record("r0", "r3") == Record(1, 0)
    assert after.pair_record("r2", "r4") == Record(0, 1)
    assert after.pair_record("r0", "r1") == Record(0, 1)
    assert after.robot_record("r1") == Record(0, 1)
    assert after.robot_record("r2") == Record(0, 1)
    assert after.pair_record("r2", "r3") == Record()  # parted by help before they finished
    assert set(after.beliefs) == set(PLACES)


def test_merging_keeps_other_teams() -> None:
    base = History({("a", "b"): Record(1, 0), ("r0", "r1"): Record(5, 5)}, {"a": Record(1, 0)}, {"a": 0.3})
    updated = History({("r0", "r1"): Record(1, 0)}, {"r0": Record(1, 0)}, {"r0": 0.5})
    merged = merge_into(base, ["r0", "r1"], updated)
    assert merged == History({("a", "b"): Record(1, 0), ("r0", "r1"): Record(1, 0)},
                             {"a": Record(1, 0), "r0": Record(1, 0)}, {"a": 0.3, "r0": 0.5})
    assert merge_into(merged, ["r0", "r1"], updated) == merged
