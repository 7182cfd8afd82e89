"""Team scenarios (issue 9): tables and targets with difficulties, up to 50 robots, light bodies,
per-robot speed and battery, failures at a time or by a seeded rate."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pydantic import ValidationError

from hfsm_sim.scenario import (
    Eq5Battery,
    FailureRate,
    LinearBattery,
    load_scenario,
    scenario_from_dict,
)

TEAM_SCENARIOS = ("team_8", "team_16", "alloc_3_tasks", "alloc_50")


def light(n: int, **extra: Any) -> dict[str, Any]:
    return {f"r{i}": {"x": -4.0 + (i % 9), "y": -4.0 + (i // 9), "body": "light", **extra} for i in range(n)}


def room(**extra: Any) -> dict[str, Any]:
    return {"room": {"width": 10.0, "depth": 10.0}, **extra}


def test_the_team_scenarios_ship() -> None:
    sizes = {name: len(load_scenario(name).robots) for name in TEAM_SCENARIOS}
    assert sizes == {"team_8": 8, "team_16": 16, "alloc_3_tasks": 10, "alloc_50": 50}
    assert all(s.body == "full" for s in load_scenario("team_16").robots.values())
    assert all(s.body == "light" for s in load_scenario("alloc_50").robots.values())


def test_one_table_is_the_shorthand_of_a_list_of_one() -> None:
    one = scenario_from_dict(room(table={"x": 1.0}, robots={"r1": {"x": 0.0, "y": 2.0}}))
    listed = scenario_from_dict(room(tables=[{"x": 1.0}], robots={"r1": {"x": 0.0, "y": 2.0}}))
    assert one.all_tables == listed.all_tables
    assert one.table_ids() == ["table1"]
    default = scenario_from_dict(room(robots={"r1": {"x": 0.0, "y": 2.0}}))
    assert len(default.all_tables) == 1
    bare = scenario_from_dict(room(tables=[], robots={"r1": {"x": 0.0, "y": 2.0}}))
    assert bare.all_tables == []


def test_tasks_are_tables_then_targets_with_difficulty_and_priority() -> None:
    scenario = scenario_from_dict(room(
        tables=[{"x": -2.0, "difficulty": 0.8, "priority": 2}, {"id": "desk", "x": 2.0}],
        targets=[{"id": "intruder", "x": 0.0, "y": 3.0, "difficulty": 0.9}],
        robots={"r1": {"x": 0.0, "y": -2.0}}))
    assert scenario.tasks() == [
        {"id": "table1", "kind": "table", "x": -2.0, "y": 0.0, "difficulty": 0.8, "priority": 2,
         "yaw": 0.0, "length": 0.8, "width": 0.5},
        {"id": "desk", "kind": "table", "x": 2.0, "y": 0.0, "difficulty": 0.5, "priority": 1,
         "yaw": 0.0, "length": 0.8, "width": 0.5},
        {"id": "intruder", "kind": "target", "x": 0.0, "y": 3.0, "difficulty": 0.9, "priority": 1},
    ]


def test_fifty_light_robots_but_at_most_sixteen_full_ones() -> None:
    assert len(scenario_from_dict(room(robots=light(50))).robots) == 50
    with pytest.raises(ValidationError, match="at most 50"):
        scenario_from_dict(room(robots=light(51)))
    full = {f"r{i}": {"x": -4.0 + (i % 9), "y": -4.0 + (i // 9)} for i in range(17)}
    with pytest.raises(ValidationError, match="17 robots with the full body"):
        scenario_from_dict(room(robots=full))


@pytest.mark.parametrize("bad", [
    room(table={}, tables=[], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(tables=[{"difficulty": 1.0}], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(tables=[{"difficulty": 0.0}], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(tables=[{"id": "a"}], targets=[{"id": "a", "x": 1.0, "y": 1.0}], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(tables=[{"x": 4.9}], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(targets=[{"id": "far", "x": 6.0, "y": 0.0}], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(targets=[{"x": 1.0, "y": 0.0}], robots={"r1": {"x": 0.0, "y": 2.0}}),
    room(robots={"r1": {"x": 0.0, "y": 2.0, "body": "wheels"}}),
    room(robots={"r1": {"x": 0.0, "y": 2.0, "speed": 0.0}}),
    room(robots={"r1": {"x": 0.0, "y": 2.0}}, failures=[{"rate": 0.0}]),
    room(robots={"r1": {"x": 0.0, "y": 2.0}}, failures=[{"rate": 1.0, "robots": ["r9"]}]),
    room(robots={"r1": {"x": 0.0, "y": 2.0}}, battery={"model": "eq5", "w_tim": 0.5}),
    room(robots={"r1": {"x": 0.0, "y": 2.0}}, battery={"model": "eq5", "m": 0.5}),
    room(robots={"r1": {"x": 0.0, "y": 2.0}}, battery={"model": "nuclear"}),
    room(robots={"r1": {"x": 0.0, "y": 2.0}}, battery={"model": "linear", "w_tim": 0.5}),
])
def test_invalid_team_scenarios_are_rejected(bad: dict[str, Any]) -> None:
    with pytest.raises(ValidationError):
        scenario_from_dict(bad)


def test_batteries_by_model_and_per_robot() -> None:
    scenario = scenario_from_dict(room(
        battery={"model": "eq5", "w_tim": 0.5, "w_dist": 0.25, "w_sped": 0.25, "tim_unit": 50.0},
        robots={"r1": {"x": 0.0, "y": 2.0}, "r2": {"x": 0.0, "y": -2.0, "battery": {"idle": 0.01}}}))
    assert isinstance(scenario.battery_of("r1"), Eq5Battery)
    assert scenario.battery_of("r2") == LinearBattery(idle=0.01)
    assert isinstance(scenario_from_dict(room(robots={"r1": {"x": 0.0, "y": 2.0}})).battery, LinearBattery)


def test_failures_at_a_time_and_by_rate() -> None:
    scenario = scenario_from_dict(room(robots=light(10), failures=[
        {"robot": "r3", "at": 4.0, "reason": "fell"}, {"rate": 2.0, "robots": ["r1", "r2", "r3"]}]))
    assert isinstance(scenario.failures[1], FailureRate)
    times = scenario.failure_times(seed=1)
    assert times == scenario.failure_times(seed=1)
    assert times != scenario.failure_times(seed=2)
    assert sorted(name for _, name, _ in times) == ["r1", "r2", "r3"]  # each fails once
    r3 = next(t for t in times if t[1] == "r3")
    assert r3[0] <= 4.0 and (r3[2] == "fell") == (r3[0] == 4.0)


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31), rate=st.floats(0.1, 10.0))
def test_rate_failures_are_seeded_and_positive(seed: int, rate: float) -> None:
    scenario = scenario_from_dict(room(robots=light(5), failures=[{"rate": rate}]))
    times = scenario.failure_times(seed)
    assert times == scenario.failure_times(seed)
    assert [name for _, name, _ in times] == [f"r{i}" for i in range(5)]
    assert all(t > 0.0 for t, _, _ in times)


def test_a_robot_is_told_its_start_as_written_not_the_jittered_truth() -> None:
    scenario = scenario_from_dict(room(robots={"r1": {"x": 0.5, "y": -2.0, "yaw": 90}}, jitter={"position": 0.1, "yaw": 10}))
    assert scenario.told_start("r1") == {"x": 0.5, "y": -2.0, "yaw": 90.0}
    x, y, _ = scenario.starts(3)["r1"]
    assert (x, y) != (0.5, -2.0)
