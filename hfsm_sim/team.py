"""The scenario's robots as bodies and robots, in scenario order: humanoids (`body: full`) and
light cylinders (`body: light`); and the hands of the humanoids over every table of the room."""

from __future__ import annotations

from dataclasses import replace
from functools import partial

import numpy as np

from hfsm_sim.base import Chassis
from hfsm_sim.battery import Battery
from hfsm_sim.body import RobotBody, build_robot
from hfsm_sim.lifting import Lifting
from hfsm_sim.light import LIGHT_BODY, LightRobot, build_light, light_motion, told_pose
from hfsm_sim.profile import ROBOT_COLOURS, BodyGeometry, MotionProfile
from hfsm_sim.raster import Renderer
from hfsm_sim.robot import Robot
from hfsm_sim.scenario import Scenario

AnyRobot = Robot | LightRobot


class Bodies:
    """The pybullet bodies of the scenario's robots, built in scenario order."""

    def __init__(self, cid: int, scenario: Scenario, seed: int, body: BodyGeometry,
                 motion: MotionProfile) -> None:
        self.full: dict[str, RobotBody] = {}
        self.light: dict[str, Chassis] = {}
        self.ids: dict[str, int] = {}
        for i, (name, pose) in enumerate(scenario.starts(seed).items()):
            colour = ROBOT_COLOURS[i % len(ROBOT_COLOURS)]
            if scenario.robots[name].body == "full":
                built = self.full[name] = build_robot(cid, body, motion, colour, pose)
                self.ids[name] = built.body
            else:
                chassis = self.light[name] = build_light(cid, LIGHT_BODY, colour, pose)
                self.ids[name] = chassis.body


class Hands:
    """A humanoid's hands over all the tables: each table has its own lifting rules."""

    def __init__(self, liftings: list[Lifting]) -> None:
        self._liftings = liftings

    def holding(self, name: str) -> bool:
        return any(lifting.holding(name) for lifting in self._liftings)

    def load(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        for lifting in self._liftings:
            if lifting.holding(name):
                return lifting.load(name)
        return np.zeros(3), np.zeros((2, 3))


def make_robots(cid: int, scenario: Scenario, seed: int, bodies: Bodies, liftings: list[Lifting],
                image_size: tuple[int, int], motion: MotionProfile, cameras: Renderer | None = None
                ) -> dict[str, AnyRobot]:
    hands = Hands(liftings)
    robots: dict[str, AnyRobot] = {}
    for i, (name, start) in enumerate(scenario.robots.items()):
        rng = np.random.default_rng([seed, i, 0x0D0])
        battery = Battery(scenario.battery_of(name))
        if name in bodies.full:
            own = motion if start.speed is None else replace(motion, forward_max=start.speed)
            if len(liftings) == 1:  # the paper's room: the one table's rules, as they were
                holding, load = partial(liftings[0].holding, name), partial(liftings[0].load, name)
            else:
                holding, load = partial(hands.holding, name), partial(hands.load, name)
            robots[name] = Robot(cid, name, bodies.full[name], own, rng, image_size, holding, load, battery,
                                 cameras=cameras, scan_rng=np.random.default_rng([seed, i, 0x5CA]))
        else:
            robots[name] = LightRobot(cid, name, bodies.light[name], light_motion(start.speed), rng,
                                      told_pose(start.x, start.y, start.yaw), battery)
    return robots
