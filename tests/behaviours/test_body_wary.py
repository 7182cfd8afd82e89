"""A wary move (hfsm_behaviours.body.Body with `blocked`): it stands still while something is in its
way, covers its whole span once the way is clear, and waits PATIENCE s at most; without `blocked`
(the paper's runs) a move is one velocity held for its span, as before."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, cast

import pytest

from hfsm.primitive import Context
from hfsm_behaviours.body import PATIENCE, Body


@dataclass
class Robot:
    profile: Any
    log: list[tuple[float, tuple[float, float, float]]] = field(default_factory=list)
    now: float = 0.0

    def set_velocity(self, forward: float, sideways: float, turn: float) -> None:
        self.log.append((self.now, (forward, sideways, turn)))

    def stop(self) -> None:
        self.set_velocity(0.0, 0.0, 0.0)


@dataclass
class Ctx:
    robot: Robot
    time: float = 0.0

    def wait(self, seconds: float) -> None:
        self.time += seconds
        self.robot.now = self.time


@dataclass
class Profile:
    forward_max: float = 0.1
    backward_max: float = 0.05
    sideways_max: float = 0.05
    turn_max: float = 0.5


def moving_time(robot: Robot, end: float) -> float:
    """Seconds the robot was commanded a non-zero walk, up to `end`."""
    total = 0.0
    for (t, v), (t2, _) in zip(robot.log, [*robot.log[1:], (end, (0.0, 0.0, 0.0))], strict=True):
        if v[0] != 0.0 or v[1] != 0.0:
            total += t2 - t
    return total


def test_a_wary_walk_stands_still_while_its_way_is_blocked_then_covers_its_span() -> None:
    robot = Robot(Profile())
    ctx = Ctx(robot)
    looks: list[float] = []

    def blocked(heading: float) -> bool:
        looks.append(heading)
        return ctx.time < 3.0  # a robot crossing its way for 3 s

    Body(cast(Context, ctx), blocked).walk(1.0)  # 10 s at 0.1 m/s
    assert ctx.time == pytest.approx(13.0)
    assert moving_time(robot, ctx.time) == pytest.approx(10.0)
    assert robot.log[0][1] == (0.0, 0.0, 0.0) and robot.log[-1][1] == (0.0, 0.0, 0.0)
    assert set(looks) == {0.0}  # straight ahead


def test_a_wary_sidestep_looks_to_its_side() -> None:
    robot = Robot(Profile())
    ctx = Ctx(robot)
    looks: list[float] = []
    Body(cast(Context, ctx), lambda h: looks.append(h) or False).crab(-0.1)
    assert looks and all(h == pytest.approx(-1.5707963) for h in looks)
    assert ctx.time == pytest.approx(2.0)


def test_a_wary_move_waits_patience_seconds_at_most() -> None:
    robot = Robot(Profile())
    ctx = Ctx(robot)
    body = Body(cast(Context, ctx), lambda h: True)  # a robot that never moves away
    body.walk(0.5)
    assert ctx.time == pytest.approx(PATIENCE + 5.0)
    assert moving_time(robot, ctx.time) == pytest.approx(5.0)


def test_without_blocked_a_move_is_one_velocity_for_its_span() -> None:
    robot = Robot(Profile())
    ctx = Ctx(robot)
    Body(cast(Context, ctx)).walk(1.0)
    assert robot.log == [(0.0, (0.1, 0.0, 0.0)), (10.0, (0.0, 0.0, 0.0))]
