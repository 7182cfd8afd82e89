from __future__ import annotations

from collections.abc import Callable

import pytest

from hfsm_sim.world import World

FAR = {"r1": {"x": -1.5, "y": -1.5, "yaw": 0.0}}


@pytest.mark.parametrize(("table", "distance", "success"), [
    ({"x": 1.5, "y": 0.0}, 0.10, True),
    ({"x": 1.4, "y": 0.0}, 0.20, False),
    ({"x": 0.0, "y": -1.6, "yaw": 90.0}, 0.0, True),
    ({"x": 0.0, "y": 1.3, "yaw": 90.0}, 0.30, False),
])
def test_table_wall_distance_and_success(world_factory: Callable[..., World],
                                         table: dict[str, float], distance: float,
                                         success: bool) -> None:
    world = world_factory(FAR, table=table)
    world.advance(0.5)
    score = world.score()
    assert score["table_wall_distance"] == pytest.approx(distance, abs=0.005)
    assert score["success"] is success
    assert score["dropped"] is False
    assert score["robot_collisions"] == 0
    assert score["time"] == pytest.approx(0.5)


def test_a_robot_collision_spoils_success(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -1.0, "y": 1.2, "yaw": 0.0},
                           "r2": {"x": -0.75, "y": 1.2, "yaw": 180.0}}, table={"x": 1.5})
    world.robots["r1"].set_velocity(0.1, 0.0, 0.0)
    world.advance(2.0)
    world.robots["r1"].set_velocity(-0.1, 0.0, 0.0)
    world.advance(1.0)
    world.robots["r1"].set_velocity(0.1, 0.0, 0.0)
    world.advance(2.0)
    score = world.score()
    assert score["robot_collisions"] == 2
    assert score["success"] is False


def test_score_keys(world_factory: Callable[..., World]) -> None:
    score = world_factory(FAR).score()
    assert {"success", "table_wall_distance", "dropped", "robot_collisions", "time"} <= set(score)
    assert score["robots_fallen"] == []
