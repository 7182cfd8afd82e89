"""A humanoid's frame corrected against the room (hfsm_behaviours/drive/localise.py, `Framed`; the
`localise` primitive): world-free with scans cast by hand, and in the simulator after a walk."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scans import ROOM, cast

from hfsm_behaviours.drive.localise import Framed, compose, relative

Pose = tuple[float, float, float]


@dataclass
class Body:
    """A humanoid by hand: where it truly is in the room, where it truly started, its odometry
    (in its own start frame, off by `drift`), and its range finder against the room's walls."""

    true: Pose
    start: Pose
    drift: Pose = (0.0, 0.0, 0.0)
    failed: bool = False
    clutter: tuple[tuple[float, float, float], ...] = ()
    scans: list[Pose] = field(default_factory=list)

    def odometry(self) -> Pose:
        return compose(relative(self.start, self.true), self.drift)

    def scan(self, beams: int, reach: float) -> list[float]:
        self.scans.append(self.true)
        return cast(self.true, beams=beams, reach=reach, clutter=self.clutter)

    def camera_model(self, camera: str = "forward") -> Any:
        return Camera(camera, self.odometry())

    def hand_load(self) -> str:
        return "the body's"


@dataclass(frozen=True)
class Camera:
    camera: str
    odom: Pose


def test_never_told_it_is_its_body_exactly() -> None:
    body = Body(true=(1.0, 2.0, 0.5), start=(0.0, 0.0, 0.0), drift=(0.3, -0.2, 0.1))
    framed = Framed(body)
    framed.update()
    assert framed.odometry() == body.odometry()
    assert framed.camera_model() == body.camera_model()
    assert framed.hand_load() == "the body's"
    assert body.scans == []  # no range finder read for it


def test_a_told_start_off_by_its_jitter_and_a_drifted_walk_are_corrected() -> None:
    true_start = (-4.0, -3.0, 0.4)
    told = (-3.9, -3.1, 0.4 - math.radians(10))  # 0.14 m and 10 degrees off, as the world jitters
    body = Body(true=(3.5, 2.0, 1.2), start=true_start, drift=(0.4, -0.3, 0.05))
    framed = Framed(body)
    believed = compose(told, body.odometry())
    assert math.dist(believed[:2], body.true[:2]) > 1.0  # by odometry and the told start
    framed.localise(told, ROOM)
    for _ in range(4):
        framed.update()
    fixed = compose(told, framed.odometry())
    assert fixed[:2] == pytest.approx(body.true[:2], abs=0.01)
    assert math.cos(fixed[2] - body.true[2]) == pytest.approx(1.0, abs=1e-4)
    assert framed.camera_model().odom == framed.odometry()  # what the cameras see is placed alike


def test_robots_crowding_it_are_not_taken_for_walls() -> None:
    true = (-1.0, 0.5, 2.0)
    crowd = tuple((-1.0 + 0.8 * math.cos(a), 0.5 + 0.8 * math.sin(a), 0.2) for a in [0.5 * k for k in range(10)])
    told = (0.0, 0.0, 0.0)
    body = Body(true=true, start=(0.1, 0.05, 0.08), clutter=crowd)
    framed = Framed(body)
    framed.localise(told, ROOM)
    for _ in range(3):
        framed.update()
    fixed = compose(told, framed.odometry())
    assert fixed[:2] == pytest.approx(true[:2], abs=0.02)


def test_a_failed_body_reads_nothing() -> None:
    body = Body(true=(0.0, 0.0, 0.0), start=(0.2, 0.0, 0.0), failed=True)
    framed = Framed(body)
    framed.localise((0.0, 0.0, 0.0), ROOM)
    framed.update()
    assert body.scans == []


@settings(max_examples=40, deadline=None)
@given(st.tuples(*[st.floats(-10, 10)] * 3), st.tuples(*[st.floats(-10, 10)] * 3))
def test_relative_undoes_compose(a: Pose, b: Pose) -> None:
    back = relative(a, compose(a, b))
    assert back[:2] == pytest.approx(b[:2], abs=1e-6)
    assert math.cos(back[2] - b[2]) == pytest.approx(1.0, abs=1e-9)


@pytest.mark.slow
def test_in_the_simulator_a_humanoid_told_its_start_knows_where_it_is_after_a_walk() -> None:
    """A humanoid put down 0.1 m and 10 degrees off where it is told (the world's jitter) walks 3 m
    along the room and turns: by the told start and odometry alone it is believed a few decimetres
    off; once localising (what the `localise` primitive asks), its frame is corrected against the
    room's walls by its range finder, among robots standing near it."""
    from hfsm_behaviours.simworld import SimWorld
    from hfsm_sim.scenario import scenario_from_dict
    from hfsm_sim.world import World

    data = {"room": {"width": 8.0, "depth": 6.0}, "tables": [], "jitter": {"position": 0.1, "yaw": 10},
            "robots": {"r1": {"x": -3.0, "y": -1.0, "yaw": 0, "body": "full"},
                       "r2": {"x": 0.0, "y": 0.0, "yaw": 90, "body": "full"},
                       "r3": {"x": 2.0, "y": -2.0, "yaw": 180, "body": "full"}}}
    world = SimWorld(World(scenario_from_dict(data), 3))
    try:
        world.start(["r1", "r2", "r3"], 0.05)
        robot = world.handle("r1")
        assert isinstance(robot, Framed)
        told = world.world.scenario.told_start("r1")
        origin = (told["x"], told["y"], math.radians(told["yaw"]))
        robot.localise(origin, (8.0, 6.0))
        robot.set_velocity(0.1, 0.0, 0.0)
        for tick in range(700):
            if tick == 500:
                robot.set_velocity(0.0, 0.0, 0.3)
            world.advance(tick)
        robot.stop()
        true = world.world.truth.robot_pose("r1")
        by_odometry = compose(origin, robot.body.odometry())
        fixed = compose(origin, robot.odometry())
        assert math.dist(fixed[:2], true[:2]) < 0.08 < math.dist(by_odometry[:2], true[:2])
        assert abs(math.degrees(math.atan2(math.sin(fixed[2] - true[2]), math.cos(fixed[2] - true[2])))) < 2.0
        assert robot.camera_model().odom == robot.odometry()
    finally:
        world.close()
