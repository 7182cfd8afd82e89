"""Localisation against the known room (hfsm_behaviours/drive/localise.py), world-free: scans cast
against a rectangle by hand, with clutter, and the pose estimate they correct."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scans import ROOM, cast

from hfsm_behaviours.drive.localise import MAX_STEP, Fix, correct


def test_a_drifted_estimate_is_brought_back_to_the_true_pose() -> None:
    true = (2.0, -1.5, 0.3)
    estimate = (2.25, -1.3, 0.3 + math.radians(4))
    fixed = correct(estimate, cast(true), ROOM)
    assert fixed == pytest.approx(true, abs=1e-3)


def test_robots_in_the_way_are_not_taken_for_walls() -> None:
    true = (-3.0, 1.0, -2.0)
    crowd = tuple((-3.0 + 1.2 * math.cos(a), 1.0 + 1.2 * math.sin(a), 0.15) for a in [0.1 * k for k in range(40)])
    fixed = correct((-2.8, 1.1, -2.03), cast(true, clutter=crowd), ROOM)
    assert fixed == pytest.approx(true, abs=0.01)


def test_along_the_only_wall_in_reach_the_estimate_keeps_its_odometry() -> None:
    true = (0.0, 4.0, 0.0)  # 0.5 m from the far wall y = 4.5; the others beyond a 3 m reach
    fixed = correct((0.3, 3.8, 0.0), cast(true, reach=3.0), ROOM, reach=3.0)
    assert fixed[1] == pytest.approx(4.0, abs=0.01)  # across the wall: corrected
    assert fixed[0] == pytest.approx(0.3, abs=0.01)  # along it: unseen, kept


def test_too_little_of_the_walls_in_sight_changes_nothing() -> None:
    assert correct((0.5, 0.5, 0.1), cast((0.0, 0.0, 0.0), reach=2.0), ROOM, reach=2.0) == (0.5, 0.5, 0.1)
    assert correct((0.5, 0.5, 0.1), [], ROOM) == (0.5, 0.5, 0.1)


def test_one_scan_moves_the_estimate_a_bounded_step() -> None:
    fixed = correct((1.0, 0.0, 0.0), cast((0.0, 0.0, 0.0)), ROOM)
    assert math.hypot(fixed[0] - 1.0, fixed[1]) <= MAX_STEP + 1e-9


@settings(max_examples=60, deadline=None)
@given(st.floats(-5.0, 5.0), st.floats(-3.5, 3.5), st.floats(-math.pi, math.pi),
       st.floats(-0.2, 0.2), st.floats(-0.2, 0.2), st.floats(-0.06, 0.06))
def test_small_errors_anywhere_in_the_room_are_corrected(x: float, y: float, yaw: float, dx: float,
                                                          dy: float, dyaw: float) -> None:
    fixed = correct((x + dx, y + dy, yaw + dyaw), cast((x, y, yaw)), ROOM)
    assert fixed[:2] == pytest.approx((x, y), abs=0.01)
    assert math.cos(fixed[2] - yaw) == pytest.approx(1.0, abs=1e-4)


@given(st.tuples(*[st.floats(-10, 10)] * 3), st.tuples(*[st.floats(-10, 10)] * 3))
def test_the_fix_takes_odometry_to_the_estimate(odom: tuple[float, float, float],
                                                 estimate: tuple[float, float, float]) -> None:
    got = Fix.between(odom, estimate).apply(odom)
    assert got[:2] == pytest.approx(estimate[:2], abs=1e-6)
    assert math.cos(got[2] - estimate[2]) == pytest.approx(1.0, abs=1e-9)


def test_in_the_simulator_a_light_robot_knows_where_it_is_after_a_long_walk() -> None:
    """30 m of circling: odometry alone drifts (seeded scale errors, yaw drift); the estimate the
    behaviours drive by, corrected by the laser against the room, stays on the robot."""
    from hfsm_behaviours.simworld import SimWorld
    from hfsm_sim.scenario import scenario_from_dict
    from hfsm_sim.world import World

    data = {"room": {"width": 8.0, "depth": 6.0}, "tables": [],
            "robots": {"r1": {"x": 0.0, "y": -1.0, "yaw": 0, "body": "light"},
                       "r2": {"x": 2.5, "y": 2.0, "yaw": 0, "body": "light"}}}
    world = SimWorld(World(scenario_from_dict(data), 4))
    try:
        world.start(["r1", "r2"], 0.05)
        robot = world.handle("r1")
        robot.set_velocity(0.5, 0.0, 0.5)
        for tick in range(1200):
            world.advance(tick)
        body = world.world.robots["r1"]
        true = world.world.truth.robot_pose("r1")
        drifted = math.dist(body.odometry()[:2], true[:2])
        assert math.dist(robot.odometry()[:2], true[:2]) < 0.05 < drifted
        assert math.cos(robot.odometry()[2] - true[2]) == pytest.approx(1.0, abs=1e-4)
    finally:
        world.close()
