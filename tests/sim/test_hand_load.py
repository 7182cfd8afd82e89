"""The hands' sense of the load (`Robot.hand_load`): the table's weight, and the give that grows
when the table is stuck against a wall while the robots walk on."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from hfsm_sim.world import World

# the 0.8 m table turned 30 degrees, its +x end 0.33 m from the wall at x = 2 (4 x 4 m room)
YAW = 30.0


def carriers(table_x: float) -> dict[str, dict[str, float]]:
    yaw = math.radians(YAW)
    nx, ny = -math.sin(yaw), math.cos(yaw)
    return {"r1": {"x": table_x - 0.34 * nx, "y": -0.34 * ny, "yaw": YAW + 90},
            "r2": {"x": table_x + 0.34 * nx, "y": 0.34 * ny, "yaw": YAW - 90}}


def lifted(world_factory: Callable[..., World], table_x: float) -> World:
    world = world_factory(carriers(table_x), table={"x": table_x, "yaw": YAW},
                          jitter={"position": 0.0, "yaw": 0.0})
    for robot in world.robots.values():
        robot.arms_lift(0.42)
    world.advance(2.5)
    return world


def test_nothing_held_feels_nothing(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": 0.0, "y": -1.0, "yaw": 0.0}})
    load = world.robots["r1"].hand_load()
    assert load.force == (0.0, 0.0, 0.0) and load.left == load.right == (0.0, 0.0, 0.0)


def test_a_lifted_table_weighs_on_the_hands_without_give(world_factory: Callable[..., World]) -> None:
    world = lifted(world_factory, 0.0)
    total = 0.0
    for robot in world.robots.values():
        load = robot.hand_load()
        assert robot.holding()
        total += load.force[2]
        assert max(abs(v) for v in (*load.left, *load.right)) < 0.005
    assert total == pytest.approx(-2.0 * 9.81, rel=0.1)  # the 2 kg table, shared


def test_a_table_stuck_at_a_wall_pulls_the_hands_back(world_factory: Callable[..., World]) -> None:
    world = lifted(world_factory, 1.2)
    r1, r2 = world.robots["r1"], world.robots["r2"]  # r1 walks right, r2 left: toward +x
    r1.set_velocity(0.0, -0.05, 0.0)
    r2.set_velocity(0.0, 0.05, 0.0)
    free = []
    while world.truth.table_wall_distance() > 0.0 and world.time < 20.0:
        world.advance(0.05)
        free.append(max(abs(r1.hand_load().left[1]), abs(r2.hand_load().right[1])))
    assert world.time < 20.0 and max(free) < 0.01  # carried freely until the corner met the wall
    world.advance(0.5)
    assert r1.holding() and r2.holding()
    assert r1.hand_load().left[1] > 0.01  # pulled back to r1's left, against its walk
    assert r2.hand_load().right[1] < -0.01  # to its right
    world.advance(1.5)
    assert world.score()["dropped"]  # walking on loses the grip
