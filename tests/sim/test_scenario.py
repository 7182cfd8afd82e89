from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml
from pydantic import ValidationError

from hfsm_sim.scenario import (
    DEFAULT_SCENARIO,
    Scenario,
    load_scenario,
    resolve,
    scenario_from_dict,
    scenario_names,
)

FIGURE_10 = {"opposite_long_side", "ahead_behind", "facing_away", "facing_table", "same_side",
             "opposite_short_side"}
BRIEF_EXAMPLE = """
room: {width: 5.0, depth: 5.0}
table: {x: 0.0, y: 0.0, yaw: 0, length: 0.8, width: 0.5}
robots:
  r1: {x: -1.2, y: 0.9, yaw: -90}
  r2: {x: 1.1, y: -1.0, yaw: 90}
jitter: {position: 0.1, yaw: 10}
"""


def test_the_example_from_the_issue_loads() -> None:
    scenario = scenario_from_dict(yaml.safe_load(BRIEF_EXAMPLE))
    assert list(scenario.robots) == ["r1", "r2"]
    assert scenario.robots["r1"].yaw == -90.0
    assert scenario.table.height == pytest.approx(0.33)


def test_all_figure_10_scenarios_ship_and_keep_their_distances() -> None:
    assert set(scenario_names()) >= FIGURE_10
    assert DEFAULT_SCENARIO in FIGURE_10
    for name in FIGURE_10:
        scenario = load_scenario(name)
        assert scenario.description
        table = scenario.table
        for start in scenario.robots.values():
            gap = math.hypot(max(0.0, abs(start.x - table.x) - table.length / 2),
                             max(0.0, abs(start.y - table.y) - table.width / 2))
            wall = min(scenario.room.width / 2 - abs(start.x),
                       scenario.room.depth / 2 - abs(start.y))
            assert gap >= 0.8 and wall >= 0.8, name


def test_jitter_is_seeded_and_bounded() -> None:
    scenario = load_scenario("same_side")
    assert scenario.starts(4) == scenario.starts(4)
    assert scenario.starts(4) != scenario.starts(5)
    for name, (x, y, yaw) in scenario.starts(4).items():
        start = scenario.robots[name]
        assert abs(x - start.x) <= 0.1 and abs(y - start.y) <= 0.1
        assert abs(math.degrees(yaw) - start.yaw) <= 10.0


@pytest.mark.parametrize("bad", [
    {"robots": {"R1": {"x": 0.0, "y": 1.0}}},
    {"robots": {"r1": {"x": 0.0, "y": 1.0, "colour": "red"}}},
    {"robots": {"r1": {"x": "0", "y": 1.0}}},
    {"robots": {}},
    {"robots": {"r1": {"x": 9.0, "y": 1.0}}},
    {"robots": {"r1": {"x": 0.0, "y": 1.0}}, "table": {"length": 0.4, "width": 0.6}},
    {"robots": {"r1": {"x": 0.0, "y": 1.0}}, "jitter": {"position": -1}},
    {"robots": {"r1": {"x": 2.2, "y": 0.0}}, "jitter": {"position": 1.0}},
    {"robots": {"r1": {"x": 0.0, "y": 1.0}}, "extra": 1},
])
def test_invalid_scenarios_are_rejected(bad: dict[str, object]) -> None:
    with pytest.raises(ValidationError):
        scenario_from_dict(bad)


def test_resolve_names_and_paths(tmp_path: Path) -> None:
    assert resolve("ahead_behind").name == "ahead_behind.yaml"
    custom = tmp_path / "mine.yaml"
    custom.write_text(BRIEF_EXAMPLE)
    assert resolve(str(custom)) == custom
    assert isinstance(load_scenario(custom), Scenario)
    with pytest.raises(FileNotFoundError, match="shipped"):
        resolve("no_such_scenario")
    with pytest.raises(FileNotFoundError, match="did you mean 'room_3_tables'"):
        resolve("room_3_tabels")
    with pytest.raises(FileNotFoundError):
        resolve(tmp_path / "missing.yaml")


def test_the_paper_scenarios_define_the_table_task_and_a_bare_one_none() -> None:
    assert {load_scenario(name).task for name in FIGURE_10} == {"table_to_wall"}
    assert scenario_from_dict(yaml.safe_load(BRIEF_EXAMPLE)).task is None


def test_an_unknown_task_is_rejected() -> None:
    with pytest.raises(ValidationError, match="table_to_wall"):
        scenario_from_dict({**yaml.safe_load(BRIEF_EXAMPLE), "task": "tables_to_wall"})


def test_the_reference_s_scenario_example_loads() -> None:
    page = (Path(__file__).resolve().parents[2] / "docs" / "REFERENCE.md").read_text()
    text = page.split("# file: two_in_a_room.yaml\n", 1)[1].split("```", 1)[0]
    assert scenario_from_dict(yaml.safe_load(text)).task == "table_to_wall"
