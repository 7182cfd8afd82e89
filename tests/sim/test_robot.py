from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from hfsm_sim.world import World

ALONE = {"r1": {"x": -1.0, "y": -1.0, "yaw": 0.0}}


def test_walking_forward_moves_about_the_commanded_distance(
        world_factory: Callable[..., World]) -> None:
    world = world_factory(ALONE)
    robot = world.robots["r1"]
    robot.set_velocity(0.1, 0.0, 0.0)
    for _ in range(40):
        world.advance(0.05)
    x, y, yaw = world.truth.robot_pose("r1")
    assert x == pytest.approx(-0.8, abs=0.01)
    assert y == pytest.approx(-1.0, abs=0.005)
    assert yaw == pytest.approx(0.0, abs=0.01)
    ox, oy, _ = robot.odometry()
    assert ox == pytest.approx(0.2, rel=0.1)
    assert abs(oy) < 0.02


def test_sideways_and_turning(world_factory: Callable[..., World]) -> None:
    world = world_factory(ALONE)
    robot = world.robots["r1"]
    robot.set_velocity(0.0, 0.05, 0.0)
    world.advance(2.0)
    assert world.truth.robot_pose("r1")[1] == pytest.approx(-0.9, abs=0.01)
    robot.set_velocity(0.0, 0.0, 0.5)
    world.advance(2.0)
    robot.stop()
    world.advance(0.5)
    assert world.truth.robot_pose("r1")[2] == pytest.approx(1.0, abs=0.03)
    assert robot.odometry()[2] == pytest.approx(1.0, abs=0.1)


def test_commands_are_clamped_to_the_profile(world_factory: Callable[..., World]) -> None:
    robot = world_factory(ALONE).robots["r1"]
    robot.set_velocity(5.0, -5.0, 9.0)
    assert robot.velocity() == (0.10, -0.05, 0.5)
    robot.set_head(10.0, 10.0)
    robot.arms_lift(3.0)
    assert robot.arms_state().target == robot.profile.arm_high


def test_a_wall_stops_the_robot(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": 1.7, "y": 0.0, "yaw": 0.0}})
    robot = world.robots["r1"]
    robot.set_velocity(0.1, 0.0, 0.0)
    world.advance(4.0)
    x = world.truth.robot_pose("r1")[0]
    assert x < 2.0 - robot._g.half_depth + 0.005
    assert x > 1.9
    assert robot.bumped()
    robot.set_velocity(-0.05, 0.0, 0.0)
    world.advance(1.0)
    assert world.truth.robot_pose("r1")[0] == pytest.approx(x - 0.05, abs=0.015)
    assert world.score()["robot_wall_collisions"] == 1


def test_robots_do_not_pass_through_each_other(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -1.0, "y": 1.2, "yaw": 0.0},
                           "r2": {"x": -0.6, "y": 1.2, "yaw": 180.0}})
    world.robots["r1"].set_velocity(0.1, 0.0, 0.0)
    world.robots["r2"].set_velocity(0.1, 0.0, 0.0)
    world.advance(3.0)
    x1, x2 = world.truth.robot_pose("r1")[0], world.truth.robot_pose("r2")[0]
    assert x2 - x1 > 2 * world.robots["r1"]._g.half_depth - 0.01
    assert world.score()["robot_collisions"] == 1


def test_walking_into_the_table_pushes_it_but_not_through(
        world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": 0.0, "y": -0.45, "yaw": 90.0}})
    world.robots["r1"].set_velocity(0.1, 0.0, 0.0)
    world.advance(2.0)
    robot_y = world.truth.robot_pose("r1")[1]
    table_y = world.truth.table_pose()[1]
    assert table_y - 0.25 >= robot_y + 0.06 - 0.01
    assert world.score()["robot_table_collisions"] == 1


def test_odometry_drift_is_seeded(world_factory: Callable[..., World]) -> None:
    poses = []
    for seed in (1, 1, 2):
        world = world_factory(ALONE, seed=seed)
        world.robots["r1"].set_velocity(0.1, 0.03, 0.2)
        for _ in range(20):
            world.advance(0.05)
        poses.append(world.robots["r1"].odometry())
    assert poses[0] == poses[1]
    assert poses[0] != poses[2]
    assert math.hypot(poses[0][0], poses[0][1]) == pytest.approx(0.1, abs=0.02)


def test_a_step_of_the_leash_is_ahead_then_leashed_then_pushed(world_factory: Callable[..., World]) -> None:
    """`_pre_step` (one function, for speed) sets the target `_ahead`, `_leashed` and `_push_target`
    set, to the bit, walking freely and pushing against a wall."""
    world = world_factory({"r1": {"x": 1.8, "y": 0.0, "yaw": 0.0}})  # 0.14 m from the wall ahead
    robot = world.robots["r1"]
    dt = 1.0 / world.physics_hz
    for command in ((0.1, 0.0, 0.0), (0.1, 0.05, 0.5), (-0.06, -0.05, -0.5), (0.0, 0.0, 0.3)):
        robot.set_velocity(*command)
        for _ in range(240):
            expected = robot._leashed(robot._ahead(dt), dt)
            robot._pre_step(dt)
            assert robot._target == expected
            world.advance(dt)
