from __future__ import annotations

from collections.abc import Callable

import pybullet as p
import pytest

from hfsm_sim.scenario import load_scenario
from hfsm_sim.world import World


def test_advance_counts_whole_physics_steps(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": 0.0, "y": -1.0}}, physics_hz=120)
    for _ in range(20):
        world.advance(0.05)
    assert world.time == pytest.approx(1.0)
    world.advance(0.001)
    assert world.time == pytest.approx(1.0)


def test_robots_keep_scenario_order_and_start_poses() -> None:
    scenario = load_scenario("facing_table")
    with World(scenario, seed=7) as world:
        assert list(world.robots) == list(scenario.robots)
        for name, (x, y, yaw) in scenario.starts(7).items():
            assert world.truth.robot_pose(name) == pytest.approx((x, y, yaw), abs=1e-6)
            assert world.robots[name].odometry() == (0.0, 0.0, 0.0)


def test_worlds_run_sequentially_and_close_their_client() -> None:
    clients = []
    for seed in range(3):
        world = World(load_scenario(), seed)
        world.advance(0.1)
        clients.append(world.client)
        world.close()
        assert not p.isConnected(clients[-1])
    with pytest.raises(RuntimeError):
        _ = world.client
    world.close()


def test_two_worlds_at_once_are_independent() -> None:
    with World(load_scenario(), 0) as a, World(load_scenario(), 0) as b:
        a.robots["r1"].set_velocity(0.1, 0.0, 0.0)
        a.advance(1.0)
        b.advance(1.0)
        assert a.truth.robot_pose("r1") != b.truth.robot_pose("r1")


def test_same_seed_same_physics() -> None:
    poses = []
    for _ in range(2):
        with World(load_scenario("same_side"), 11) as world:
            world.robots["r1"].set_velocity(0.1, 0.0, 0.3)
            world.robots["r2"].set_velocity(0.1, -0.05, -0.2)
            for _ in range(40):
                world.advance(0.05)
            poses.append([world.truth.robot_pose(n) for n in world.robots]
                         + [world.truth.table_pose()])
    assert poses[0] == poses[1]
