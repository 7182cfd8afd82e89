"""Light robots (camera-less cylinders driven by velocity), several tables, and batteries that
spend on radio messages, in the simulated world."""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import pytest

from hfsm_sim.light import LightRobot
from hfsm_sim.robot import Robot
from hfsm_sim.scenario import scenario_from_dict
from hfsm_sim.world import World


@pytest.fixture
def worlds() -> Iterator[list[World]]:
    made: list[World] = []
    yield made
    for world in made:
        world.close()


def make(worlds: list[World], robots: dict[str, Any], **extra: Any) -> World:
    data = {"room": {"width": 8.0, "depth": 8.0}, "tables": [], "robots": robots, **extra}
    world = World(scenario_from_dict(data), 0)
    worlds.append(world)
    return world


def test_a_light_robot_drives_at_its_speed_and_knows_where_it_is(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": -2.0, "y": 1.0, "yaw": 90, "body": "light", "speed": 1.0}})
    robot = world.robots["r1"]
    assert isinstance(robot, LightRobot) and not robot.holding()
    assert robot.odometry() == pytest.approx((-2.0, 1.0, math.pi / 2))  # told its start, room frame
    robot.set_velocity(2.0, 0.0, 0.0)  # clamped to its speed
    for _ in range(40):
        world.advance(0.05)
    x, y, _ = world.truth.robot_pose("r1")
    assert (x, y - 1.0) == pytest.approx((-2.0, 2.0), abs=0.1)
    assert robot.odometry()[:2] == pytest.approx((x, y), abs=0.1)
    robot.set_velocity(0.0, -1.0, 0.0)  # holonomic: sideways as fast, to its right (+x here)
    for _ in range(20):
        world.advance(0.05)
    assert world.truth.robot_pose("r1")[0] == pytest.approx(-1.0, abs=0.1)


def test_robots_that_drive_into_each_other_collide_once(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": -1.0, "y": 0.0, "yaw": 0, "body": "light"},
                          "r2": {"x": 1.0, "y": 0.0, "yaw": 180, "body": "light"},
                          "r3": {"x": 0.0, "y": 2.0}})
    assert isinstance(world.robots["r3"], Robot)
    for name in ("r1", "r2"):
        world.robots[name].set_velocity(0.5, 0.0, 0.0)
    bumped = False
    for _ in range(80):
        world.advance(0.05)
        bumped = bumped or world.robots["r1"].bumped()
    assert bumped
    assert world.score()["robot_collisions"] == 1
    assert world.truth.robot_pose("r2")[0] - world.truth.robot_pose("r1")[0] == pytest.approx(0.3, abs=0.05)


def test_a_failed_light_robot_stops_and_goes_silent(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": -1.0, "y": 0.0, "body": "light"}, "r2": {"x": 1.0, "y": 0.0, "body": "light"}})
    world.robots["r1"].set_velocity(0.5, 0.0, 0.0)
    world.fail("r1")
    world.advance(1.0)
    assert world.robots["r1"].failed and world.truth.robot_pose("r1")[0] == pytest.approx(-1.0, abs=0.02)
    assert not world.radio.send("r1", "r2", "hello", world.time)


def test_several_tables_in_the_poses_and_the_score(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": 0.0, "y": 0.0, "body": "light"}},
                 tables=[{"x": -2.0, "y": 0.0}, {"x": 3.0, "y": 0.0, "yaw": 90}])
    world.advance(0.5)
    assert [t[:2] for t in world.poses()["tables"]] == [[-2.0, 0.0], [3.0, 0.0]]
    score = world.score()
    assert score["table_wall_distances"] == pytest.approx([1.6, 0.75], abs=0.01)
    assert score["table_wall_distance"] == pytest.approx(1.6, abs=0.01)
    assert not score["success"]
    empty = make(worlds, {"r1": {"x": 0.0, "y": 0.0, "body": "light"}})
    assert empty.score()["table_wall_distance"] is None and empty.poses()["tables"] == []
    assert "targets" not in empty.poses()
    aimed = make(worlds, {"r1": {"x": 0.0, "y": 0.0, "body": "light"}}, targets=[{"id": "t1", "x": 2.0, "y": 1.0}])
    assert aimed.poses()["targets"] == [["t1", 2.0, 1.0]]


def test_batteries_spend_on_messages_read(worlds: list[World]) -> None:
    robots = {"r1": {"x": -1.0, "y": 0.0, "body": "light"}, "r2": {"x": 1.0, "y": 0.0, "body": "light"}}
    world = make(worlds, robots, battery={"idle": 0.0, "walk": 0.0, "read": 0.01})
    for i in range(5):
        world.radio.send("r1", "r2", i, world.time)
    world.radio.deliver(world.time + 1.0)
    world.advance(0.05)
    assert world.robots["r2"].battery() == pytest.approx(0.95)
    assert world.robots["r1"].battery() == pytest.approx(1.0)


def test_the_eq5_battery_falls_with_distance_and_reads(worlds: list[World]) -> None:
    robots = {"r1": {"x": -1.0, "y": 0.0, "body": "light", "speed": 1.0}, "r2": {"x": 1.0, "y": 2.0, "body": "light"}}
    world = make(worlds, robots, battery={"model": "eq5", "empty": 0.5})
    assert world.robots["r1"].battery() == 1.0
    world.robots["r1"].set_velocity(1.0, 0.0, 0.0)
    for _ in range(20):
        world.advance(0.05)
    level = world.robots["r1"].battery()
    dist, sped = 1.0, 1.0
    expected = (1 + (1 + dist) ** -0.5 + (1 + sped) ** -0.5) / 3
    assert level == pytest.approx(expected, abs=0.02)
    assert world.robots["r2"].battery() == pytest.approx(1.0)
    assert not world.robots["r1"].battery_empty()


def test_the_proximity_sensor_finds_robots_and_walls_not_the_floor(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": 3.0, "y": 0.0, "yaw": 90, "body": "light"},
                          "r2": {"x": 2.4, "y": 0.0, "yaw": 0, "body": "light"}},
                 jitter={"position": 0.0, "yaw": 0.0})
    world.advance(0.05)
    robot = world.robots["r1"]
    assert isinstance(robot, LightRobot)
    seen = robot.nearby(1.0)
    assert len(seen) == 2  # r2 on its left (0.45 m to its side), the wall at x = 4 on its right
    assert seen[0] == pytest.approx((0.0, 0.45), abs=0.02)
    assert seen[1] == pytest.approx((0.0, -1.0), abs=0.02)
    assert robot.nearby(0.2) == []


def test_the_range_finder_sees_the_walls_and_other_robots(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": 1.0, "y": -1.0, "yaw": 0, "body": "light"},
                          "r2": {"x": 1.0, "y": 1.0, "yaw": 0, "body": "light"}},
                 jitter={"position": 0.0, "yaw": 0.0})
    world.advance(0.05)
    robot = world.robots["r1"]
    assert isinstance(robot, LightRobot)
    ranges = robot.scan(4, 20.0)  # ahead, left, behind, right in a room 8 x 8 centred on 0
    assert ranges[0] == pytest.approx(3.0, abs=0.05)  # the wall at x = 4
    assert ranges[1] == pytest.approx(2.0 - 0.15, abs=0.05)  # r2's side, 2 m to its left
    assert ranges[2] == pytest.approx(5.0, abs=0.05)
    assert ranges[3] == pytest.approx(3.0, abs=0.05)
    assert robot.scan(4, 2.5) == [2.5, pytest.approx(1.85, abs=0.05), 2.5, 2.5]  # nothing within reach


def test_the_humanoid_range_finder_sees_robots_and_walls_over_a_standing_table(worlds: list[World]) -> None:
    world = make(worlds, {"r1": {"x": 1.0, "y": -1.0, "yaw": 0},
                          "r2": {"x": 1.0, "y": 1.0, "yaw": 0}},
                 tables=[{"id": "t", "x": 2.5, "y": -1.0, "yaw": 90}], jitter={"position": 0.0, "yaw": 0.0})
    world.advance(0.05)
    robot = world.robots["r1"]
    assert isinstance(robot, Robot)
    ranges = robot.scan(4, 20.0)  # ahead (over the table, to the wall), left, behind, right
    assert ranges[0] == pytest.approx(3.0, abs=0.05)
    assert ranges[1] == pytest.approx(2.0 - 0.14, abs=0.05)  # r2's side (0.28 m wide), 2 m to its left
    assert ranges[2] == pytest.approx(5.0, abs=0.05)
    assert ranges[3] == pytest.approx(3.0, abs=0.05)
    robot._fail()
    assert robot.scan(4, 20.0) == []
