from __future__ import annotations

import math
from collections.abc import Callable

import pytest

from hfsm_sim.world import World

ACROSS = {"r1": {"x": 0.0, "y": -0.34, "yaw": 90.0}, "r2": {"x": 0.0, "y": 0.34, "yaw": -90.0}}


def test_two_sided_lift_and_five_side_steps_carry_the_table(
        world_factory: Callable[..., World]) -> None:
    world = world_factory(ACROSS)
    r1, r2 = world.robots["r1"], world.robots["r2"]
    r1.arms_lift(0.42)
    r2.arms_lift(0.42)
    world.advance(2.5)
    assert r1.holding() and r2.holding()
    assert r1.arms_state().settled
    assert world.truth.table_pose()[2] == pytest.approx(0.12, abs=0.01)
    for _ in range(5):
        r1.set_velocity(0.0, -0.05, 0.0)
        r2.set_velocity(0.0, 0.05, 0.0)
        world.advance(1.0)
        r1.stop()
        r2.stop()
        world.advance(0.2)
    x, y, lift, _ = world.truth.table_pose()
    assert x == pytest.approx(0.25, abs=0.02)
    assert abs(y) < 0.02 and lift > 0.1
    assert math.degrees(world.truth.table_tilt()) < 2.0
    r1.arms_lower()
    r2.arms_lower()
    world.advance(2.5)
    assert not r1.holding() and not r2.holding()
    assert abs(world.truth.table_pose()[2]) < 0.005
    assert not world.score()["dropped"]


def test_one_sided_lift_tilts_then_drops_the_table(world_factory: Callable[..., World]) -> None:
    world = world_factory(ACROSS)
    r1 = world.robots["r1"]
    r1.arms_lift(0.36)
    world.advance(1.8)
    assert r1.holding()
    assert 5.0 < math.degrees(world.truth.table_tilt()) < 20.0
    assert not world.score()["dropped"]
    r1.arms_lift(0.5)
    world.advance(1.5)
    assert not r1.holding()
    assert world.score()["dropped"]


def test_hands_out_of_reach_grip_nothing(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": 0.0, "y": -0.6, "yaw": 90.0}})
    world.robots["r1"].arms_lift(0.45)
    world.advance(2.8)
    assert not world.robots["r1"].holding()
    assert world.truth.table_pose()[2] == pytest.approx(0.0, abs=0.002)


def test_short_side_does_not_grip(world_factory: Callable[..., World]) -> None:
    world = world_factory({"r1": {"x": -0.49, "y": 0.0, "yaw": 0.0}})
    world.robots["r1"].arms_lift(0.45)
    world.advance(2.8)
    assert not world.robots["r1"].holding()


def test_diverging_robots_drop_the_table(world_factory: Callable[..., World]) -> None:
    world = world_factory(ACROSS)
    r1, r2 = world.robots["r1"], world.robots["r2"]
    r1.arms_lift(0.42)
    r2.arms_lift(0.42)
    world.advance(2.5)
    r1.set_velocity(-0.06, 0.0, 0.0)
    world.advance(3.0)
    assert world.score()["dropped"]
