"""World: one pybullet DIRECT client holding a room, its tables and the scenario's robots."""

from __future__ import annotations

from typing import Any, Protocol

import pybullet as p

from hfsm_sim.camera import TinyRenderer
from hfsm_sim.lifting import Lifting
from hfsm_sim.profile import DEFAULT_BODY, DEFAULT_MOTION, BodyGeometry, MotionProfile
from hfsm_sim.radio import Radio
from hfsm_sim.raster import Rasteriser
from hfsm_sim.robot import Robot
from hfsm_sim.room import build_room, build_table
from hfsm_sim.scenario import Scenario
from hfsm_sim.scorer import Scorer
from hfsm_sim.team import AnyRobot, Bodies, make_robots
from hfsm_sim.truth import Truth


class Recorder(Protocol):
    every: float

    def capture(self, world: World) -> None: ...
    def close(self) -> None: ...


class World:
    """A simulated run. Time starts at 0 and only moves in `advance`."""

    def __init__(self, scenario: Scenario, seed: int = 0, *, physics_hz: int = 120,
                 image_size: tuple[int, int] = (160, 120), radio_latency: float = 0.1,
                 radio_loss: float = 0.0, success_distance: float = 0.15,
                 recorder: Recorder | None = None, motion: MotionProfile = DEFAULT_MOTION,
                 body: BodyGeometry = DEFAULT_BODY, renderer: str = "raster") -> None:
        self.scenario, self.seed, self.physics_hz = scenario, seed, physics_hz
        self.image_size = image_size
        self._cid: int | None = p.connect(p.DIRECT)
        self._steps = 0
        try:  # a failed set-up must not leave the client connected
            cid = self._cid
            p.setGravity(0.0, 0.0, -9.81, physicsClientId=cid)
            p.setTimeStep(1.0 / physics_hz, physicsClientId=cid)
            p.setPhysicsEngineParameter(deterministicOverlappingPairs=1, physicsClientId=cid)
            room = build_room(cid, scenario.room)
            tables = [build_table(cid, spec) for spec in scenario.all_tables]
            bodies = Bodies(cid, scenario, seed, body, motion)
            self._hand_points: dict[int, list[tuple[float, float, float]]] = {}  # this step's
            self._liftings = [Lifting(cid, table, bodies.full, dt=1.0 / physics_hz,
                                      hand_points=self._hand_points) for table in tables]
            # one renderer for every robot's cameras; "tiny" (pybullet's) only to compare with
            cameras = TinyRenderer(cid) if renderer == "tiny" else Rasteriser(cid, clock=lambda: self._steps)
            self.robots: dict[str, AnyRobot] = make_robots(cid, scenario, seed, bodies, self._liftings,
                                                           image_size, motion, cameras)
            arms = {name: r for name, r in self.robots.items() if isinstance(r, Robot)}
            for lifting in self._liftings:
                lifting.bind(arms)
            # a run's own loss wins; without one (0), the scenario's `radio: {loss: ...}`
            self.radio = Radio(radio_latency, radio_loss or scenario.radio.loss, seed)
            self.truth = Truth(cid, scenario.room, room, tables, bodies.full, bodies.ids)
            self._scorer = Scorer(cid, self.truth, success_distance)
            self._recorder = recorder
            self.labels: dict[str, str] = {}  # shown beside each robot's name in videos (role, behaviour)
            self._next_capture = 0.0
        except BaseException:
            p.disconnect(physicsClientId=self._cid)
            self._cid = None
            raise
        self._capture()

    def record(self, recorder: Recorder) -> None:
        """Start recording now, the first frame at once (instead of passing `recorder` to __init__)."""
        self._recorder = recorder
        self._next_capture = self.time
        self._capture()

    @property
    def time(self) -> float:
        return self._steps / self.physics_hz

    @property
    def client(self) -> int:
        if self._cid is None:
            raise RuntimeError("world is closed")
        return self._cid

    def advance(self, seconds: float) -> None:
        """Step physics for `seconds` (rounded to whole physics steps) under held commands."""
        cid, dt = self.client, 1.0 / self.physics_hz
        end = round((self.time + seconds) * self.physics_hz)
        start = self._steps
        robots = list(self.robots.values())
        raised = any(r._arms_active() for r in robots if isinstance(r, Robot))  # commands hold over the span
        for robot in robots:
            robot._before_advance(dt)
        moving = [r for r in robots if r._cmd != (0.0, 0.0, 0.0)]  # a body standing still has no step
        while self._steps < end:
            for robot in moving:
                robot._pre_step(dt)
            p.stepSimulation(physicsClientId=cid)
            self._steps += 1
            self._hand_points.clear()
            for lifting in self._liftings:
                lifting.update(raised)
            self._scorer.observe()
            self._capture()
        bumps, reads = self._scorer.take_bumps(), self.radio.take_reads()
        for name, robot in self.robots.items():
            robot._after_advance(bumps[name], (self._steps - start) / self.physics_hz, reads.get(name, 0))
        self._scorer.check_poses()

    def fail(self, name: str) -> None:
        """Robot `name` fails: it stops, drops what it holds and goes silent on the radio."""
        robot = self.robots[name]
        robot._fail()
        if isinstance(robot, Robot):
            for lifting in self._liftings:
                lifting.let_go(name)
        self.radio.silence(name)

    def _capture(self) -> None:
        if self._recorder is not None and self.time + 1e-9 >= self._next_capture:
            self._recorder.capture(self)
            self._next_capture += self._recorder.every

    @property
    def dropped(self) -> bool:
        return any(lifting.dropped for lifting in self._liftings) or self._scorer.dropped

    def poses(self) -> dict[str, Any]:
        """Where everything is (ground truth, for people watching: the monitor's room view), rounded
        to the millimetre and the tenth of a milliradian."""
        truth, room = self.truth, self.scenario.room
        robots = {name: [round(v, 4) for v in truth.robot_pose(name)] for name in self.robots}
        tables = []
        for i, body in enumerate(truth.tables):
            x, y, lift, yaw = truth.table_pose(i)
            tables.append([round(x, 4), round(y, 4), round(yaw, 4), body.spec.length, body.spec.width,
                           round(lift, 4)])
        poses: dict[str, Any] = {"room": [room.width, room.depth], "robots": robots, "tables": tables}
        if self.scenario.targets:  # [id, x, y]: where the team is sent (the paper's rooms have none)
            poses["targets"] = [[t.id, t.x, t.y] for t in self.scenario.targets]
        return poses

    def score(self) -> dict[str, Any]:
        """Ground-truth outcome; see hfsm_sim.scorer.Scorer.score for the keys."""
        return self._scorer.score(self.time, dropped=self.dropped)

    def close(self) -> None:
        recorder, self._recorder = self._recorder, None
        try:
            if recorder is not None:
                recorder.close()  # OSError when the video or the picture could not be written
        finally:
            if self._cid is not None:
                p.disconnect(physicsClientId=self._cid)
                self._cid = None

    def __enter__(self) -> World:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
