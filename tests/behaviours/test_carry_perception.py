"""hfsm_sim.perception (edge, reach, walls) against ground truth: the near edge, the table's reach to each side,
the wall to each side, from a robot standing at the table as the carry leaves it."""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest
from carry_scene import GRIP_Y, TABLE_X, at_table

from hfsm_sim import World, scenario_from_dict
from hfsm_sim.perception import near_edge, side_extent, wall_to_side
from hfsm_sim.perception.reach import _this_table

# (along m, away m, turned deg) from square at grip depth
POSES = [(0.0, 0.0, 0.0), (0.1, 0.02, 7.0), (-0.1, -0.01, -7.0), (0.05, 0.03, 15.0)]


@pytest.fixture(params=POSES, ids=lambda p: f"along{p[0]}_away{p[1]}_yaw{p[2]}")
def scene(request: pytest.FixtureRequest) -> Iterator[tuple[World, tuple[float, float, float]]]:
    offset = request.param
    with World(scenario_from_dict(at_table(offset, None)), 0) as world:
        yield world, offset


def look(world: World, yaw: float, pitch: float) -> None:
    world.robots["r1"].set_head(yaw, pitch)
    world.advance(1.0)


def test_near_edge_distance_and_turn(scene: tuple[World, tuple[float, float, float]]) -> None:
    world, (_, away, turned) = scene
    look(world, 0.0, 0.5)
    robot = world.robots["r1"]
    edge = near_edge(robot.image("down"), robot.camera_model("down"))
    assert edge.found
    assert edge.distance == pytest.approx((GRIP_Y + away - 0.25) * math.cos(math.radians(turned)), abs=0.01)
    assert math.degrees(edge.turn) == pytest.approx(-turned, abs=1.5)


def test_side_extents_tell_the_longer_side(scene: tuple[World, tuple[float, float, float]]) -> None:
    world, (along, _, _) = scene
    robot = world.robots["r1"]
    look(world, 0.0, 0.5)
    turn = near_edge(robot.image("down"), robot.camera_model("down")).turn
    reach = {}
    for side, yaw in (("left", 1.3), ("right", -1.3)):
        look(world, yaw, 0.45)
        reach[side] = side_extent(robot.image("forward"), robot.camera_model("forward"), side, turn)
    # r1 faces +y: its left is -x, so standing `along` +x leaves more table on its left
    assert reach["left"].lateral == pytest.approx(0.4 + along, abs=0.02)
    assert reach["right"].lateral == pytest.approx(0.4 - along, abs=0.02)


@pytest.mark.parametrize("table_x", [0.0, TABLE_X, 1.9])
def test_wall_to_the_right(table_x: float) -> None:
    with World(scenario_from_dict(at_table((0.0, 0.0, 0.0), None, table_x=table_x)), 0) as world:
        look(world, -2.0, 0.5)
        robot = world.robots["r1"]
        seen = wall_to_side(robot.image("forward"), robot.camera_model("forward"), "right")
        assert seen.found
        assert seen.distance == pytest.approx(2.5 - table_x, abs=0.03)


@pytest.mark.parametrize("turned", [-12.0, 12.0])
def test_an_oblique_wall_is_seen_as_a_line(turned: float) -> None:
    """Turned `turned` degrees, r1 sees the wall to its right (the room's +x wall) at its
    distance, its normal off the body's right axis by as much."""
    with World(scenario_from_dict(at_table((0.0, 0.0, turned), None, table_x=1.2)), 0) as world:
        look(world, -2.0, 0.5)
        robot = world.robots["r1"]
        seen = wall_to_side(robot.image("forward"), robot.camera_model("forward"), "right")
        x = world.truth.robot_pose("r1")[0]
        assert seen.found
        assert seen.distance == pytest.approx(2.5 - x, abs=0.03)
        assert math.degrees(seen.normal) == pytest.approx(-90.0 - turned, abs=2.0)


def test_no_table_no_edge() -> None:
    scenario = {"room": {"width": 5.0, "depth": 5.0}, "robots": {"r1": {"x": 0.0, "y": -2.0, "yaw": -90.0}}}
    with World(scenario_from_dict(scenario), 0) as world:
        look(world, 0.0, 0.5)
        robot = world.robots["r1"]
        assert not near_edge(robot.image("down"), robot.camera_model("down")).found


def _reaches(scenario: dict[str, Any]) -> dict[str, Any]:
    """r1 at its table's edge looks down, then to each side: the side reach measured each way."""
    with World(scenario_from_dict(scenario), 0) as world:
        robot = world.robots["r1"]
        look(world, 0.0, 0.5)
        turn = near_edge(robot.image("down"), robot.camera_model("down")).turn
        reach = {}
        for side, yaw in (("left", 1.3), ("right", -1.3)):
            look(world, yaw, 0.45)
            reach[side] = side_extent(robot.image("forward"), robot.camera_model("forward"), side, turn)
    return reach


@pytest.mark.parametrize("other_x", [1.4, 1.6])
def test_a_second_table_in_line_does_not_lengthen_the_side(other_x: float) -> None:
    """Another table of the room further along the same line (issue 10): the reach to that side
    is still the held table's, not the far end of the other one."""
    scenario = at_table((0.0, 0.0, 0.0), None, table_x=0.0)
    del scenario["table"]
    scenario["tables"] = [{"x": 0.0}, {"x": other_x, "y": 0.0}]
    reach = _reaches(scenario)
    assert reach["left"].lateral == pytest.approx(0.4, abs=0.02)
    assert reach["right"].lateral == pytest.approx(0.4, abs=0.02)
    assert not reach["right"].clipped


@pytest.mark.parametrize(("other_y", "other_x"), [(1.5, 0.6), (1.4, 0.9), (1.2, 0.6), (1.6, 0.3)])
def test_a_table_behind_reaching_past_the_end_does_not_lengthen_the_side(
    other_y: float, other_x: float
) -> None:
    """Another table standing behind the held one, parallel, its end reaching past the held table's
    end on the right (generated room close-34000: table1 at its wall 1.4 m behind table2, whose
    leader then measured 0.33 m left and 1.07 m right and crabbed to and fro until the limit): the
    reach is still the held table's."""
    scenario = at_table((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), table_x=0.0)
    del scenario["table"]
    scenario["tables"] = [{"x": 0.0}, {"x": other_x, "y": other_y, "length": 1.04, "width": 0.42}]
    reach = _reaches(scenario)
    assert reach["left"].lateral == pytest.approx(0.4, abs=0.02)
    assert reach["right"].lateral == pytest.approx(0.4, abs=0.02)


def test_a_table_behind_the_robot_is_not_the_held_one() -> None:
    """Top pixels of a table behind the robot (across < 0; the side-by-side room: table1 at its wall
    behind and to the right of table2's assistant, whose right reach then measured 3.2-3.6 m) and of one
    beyond a gap ahead are cut; the held table's top, from its near edge on, is kept."""
    across = np.array([-1.0, -0.8, -0.6, 0.1, 0.3, 0.5, 0.6, 1.5, 1.7])
    ok = np.ones(across.size, dtype=bool)
    kept, top = _this_table(across, ok, ok.copy(), 0.3)
    assert list(top) == [False, False, False, True, True, True, True, False, False]
    assert list(kept) == list(top)
