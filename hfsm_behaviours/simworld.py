"""The pybullet world (sim) seen through the engine's world seam (hfsm.world).

Scenario files are read like machine files: every error at its line and column. Messages go
through the sim's radio (latency, loss) into the engine's mailboxes.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from hfsm import located
from hfsm.errors import UsageError
from hfsm.primitive import Message
from hfsm.runtime.program import span_ticks
from hfsm.world import InputSpec
from hfsm.yamlio import read_mapping
from hfsm_behaviours.drive.localise import FRAMED_EVERY, SCAN_EVERY, Framed, Localised
from hfsm_behaviours.inputs import SIM_INPUTS
from hfsm_behaviours.senses import Senses
from hfsm_sim import Scenario, World, resolve
from hfsm_sim.light import LightRobot
from hfsm_sim.recorder import Recorder
from hfsm_sim.team import AnyRobot

SCORE_KEYS = ("success", "table_wall_distance", "dropped", "robot_collisions", "time")  # table_to_wall
MANY_TABLES_KEYS = ("table_wall_distances",)  # table_to_wall in a room of several tables
ROBOT_KEYS = ("robot_collisions", "time")  # a scenario with no task
SUCCESS_DISTANCE = 0.15  # metres: a table this near a wall is at it (hfsm_sim.scorer's default)


def load_scenario(name_or_path: str) -> tuple[Scenario, str]:
    """A scenario by shipped name or file path, checked with positions; and its display name."""
    try:
        path = resolve(name_or_path)
    except FileNotFoundError as exc:
        raise UsageError(f"--scenario: {exc}") from None
    return located.validate(Scenario, read_mapping(path, "a scenario")), path.stem


POSE_EVERY = 0.5  # seconds between the poses the trace gets


class Labels:
    """Reads the trace as it is written: for each robot, the state under its top machine (the role,
    as `leader`) and the behaviour it runs deepest, shown beside its name in the video."""

    def __init__(self, labels: dict[str, str]) -> None:
        self.labels = labels

    def write(self, record: dict[str, Any]) -> None:
        if record["kind"] != "enter" or len(record["path"]) < 2:
            return
        path = record["path"]
        self.labels[record["agent"]] = f"{path[1]}: {record.get('do') or path[-1]}" if len(path) > 2 \
            else path[1]

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


class SimWorld:
    """Implements hfsm.world.World over a sim.World."""

    name = "sim"
    static = False

    def __init__(
        self,
        world: World,
        *,
        progress_every: float = 0.0,
        outputs: Sequence[Path] = (),
        default_trace: Path | None = None,
        recorder: Recorder | None = None,
    ) -> None:
        self.world = world
        self._recorder = recorder  # attached when the run starts: a run refused writes nothing
        self.default_trace = default_trace
        self.dt = 0.05
        self.progress_every = progress_every
        self._outputs = list(outputs)
        self._next_progress = progress_every
        self._senses: dict[str, Senses] = {}
        self._radio_delay: dict[str, float] = {}  # receiver -> what its latest message took
        self._failures = world.scenario.failure_times(world.seed)
        truth = world.truth
        self._table_starts = [truth.table_pose(i)[:2] for i in range(len(truth.tables))]
        room = (world.scenario.room.width, world.scenario.room.depth)
        # Light robots know where they are by odometry corrected against the room by their laser;
        # the humanoids by odometry from where they were told they started, corrected the same way
        # once their machine asks for it (the `localise` primitive), else by odometry alone.
        self._localised = {name: Localised(robot, room) for name, robot in world.robots.items()
                           if isinstance(robot, LightRobot)}
        self._framed = {name: Framed(robot) for name, robot in world.robots.items()
                        if not isinstance(robot, LightRobot)}

    @property
    def outputs(self) -> list[Path]:
        """The files the world writes when it closes (video, final picture)."""
        return list(self._outputs)

    @property
    def video_rate(self) -> float:
        """Simulated seconds a second of its video shows (a frame every `every` s at `fps`)."""
        recorder = self._recorder
        return recorder.every * recorder.fps if recorder is not None else 5.0

    def agent_names(self) -> list[str]:
        return list(self.world.robots)

    def start(self, agents: Sequence[str], dt: float) -> None:
        self.dt = dt
        if self._recorder is not None:
            self.world.record(self._recorder)

    def handle(self, agent: str) -> AnyRobot | Localised | Framed:
        return self._localised.get(agent) or self._framed.get(agent) or self.world.robots[agent]

    def inputs(self) -> Mapping[str, InputSpec]:
        return SIM_INPUTS

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        if name == "radio_delay":
            return self._radio_delay.get(agent, 0.0)
        senses = self._senses.get(agent)
        if senses is None:
            own = list(self.world.robots).index(agent)  # robots wear the colours in scenario order
            scenario = self.world.scenario
            told = {"start": scenario.told_start(agent),
                    "room": {"width": scenario.room.width, "depth": scenario.room.depth}}
            senses = self._senses[agent] = Senses(self.handle(agent), own, scenario.tasks(), told)
        return senses.read(name, tick)

    def post(self, message: Message) -> None:
        self.world.radio.send(message.sender, message.to, message, message.sent_tick * self.dt)

    def collect(self, tick: int) -> list[Message]:
        messages: list[Message] = [payload for _, _, payload in self.world.radio.deliver(tick * self.dt)]
        for message in messages:  # stamped when sent, read when heard, by the robots' synchronised clocks
            self._radio_delay[message.to] = round((tick - message.sent_tick) * self.dt, 6)
        return messages

    def next_delivery(self) -> int | None:
        return None

    def advance(self, tick: int) -> None:
        # To the exact time of the next tick, so that a dt that is not a whole number of physics
        # steps does not drift: the world rounds the end of each span to a physics step.
        self.world.advance((tick + 1) * self.dt - self.world.time)
        if tick % max(1, round(SCAN_EVERY / self.dt)) == 0:
            for localised in self._localised.values():
                if not localised.body.failed:
                    localised.update()
        if tick % max(1, round(FRAMED_EVERY / self.dt)) == 0:
            for framed in self._framed.values():
                framed.update()
        if self.progress_every and self.world.time + 1e-9 >= self._next_progress:
            self._next_progress += self.progress_every
            self._progress()

    def trace_records(self, tick: int) -> list[dict[str, Any]]:
        """Every POSE_EVERY seconds, a `pose` record of the room for the monitor's view from above."""
        if tick % max(1, round(POSE_EVERY / self.dt)):
            return []
        return [{"t": round(tick * self.dt, 9), "agent": "world", "path": [], "kind": "pose",
                 **self.world.poses(), "sensed": self._sensed()}]

    def _sensed(self) -> dict[str, dict[str, Any]]:
        """What each robot last sensed (`senses.SHOWN`, in its own start frame, with the tick it was
        read) and where it was told it started: what it believes, drawn beside the truth."""
        out: dict[str, dict[str, Any]] = {}
        for name, senses in sorted(self._senses.items()):
            start = self.world.scenario.told_start(name)
            out[name] = {"start": [start["x"], start["y"], start["yaw"]],
                         **{k: {"t": round(t * self.dt, 9), "value": v}
                            for k, (t, v) in sorted(senses.last.items())}}
        return out

    def label_sink(self) -> Labels | None:
        """A trace sink that labels each robot in the video with its role and current behaviour; None
        without a video (`--no-video`): then the trace file is the run's only sink, and the engine
        writes it as text (hfsm.runtime.records.TextRecords, the same bytes for less work)."""
        return None if self._recorder is None else Labels(self.world.labels)

    def failures(self, tick: int) -> Sequence[tuple[str, str]]:
        """The scenario's failures due now (`at:` times and the seeded `rate:` ones), and robots
        whose battery is empty."""
        due = [(name, reason) for at, name, reason in self._failures if span_ticks(at, self.dt) == tick]
        for name, robot in self.world.robots.items():
            if robot.battery_empty() and not robot.failed:
                due.append((name, "battery empty"))
        return due

    def fail(self, agent: str) -> None:
        self.world.fail(agent)

    def _tables(self) -> dict[str, dict[str, float]]:
        """Each table's gap to the nearest wall and how far it moved (the scorer's truth, for people)."""
        truth, ids = self.world.truth, self.world.scenario.table_ids()
        out = {}
        for i, (name, start) in enumerate(zip(ids, self._table_starts, strict=True)):
            x, y = truth.table_pose(i)[:2]
            out[name] = {"wall_distance": round(truth.table_wall_distance(i), 3),
                         "moved": round(math.dist((x, y), start), 3)}
        return out

    def _progress(self) -> None:
        minutes, seconds = divmod(self.world.time, 60)
        line = f"simulated {int(minutes):02d}:{seconds:04.1f}"
        if len(self._table_starts) > 1:
            tables = self._tables()
            at_wall = sum(t["wall_distance"] <= SUCCESS_DISTANCE for t in tables.values())
            failed = sum(r.failed for r in self.world.robots.values())
            line += f"  tables at a wall {at_wall}/{len(tables)}  robots failed {failed}"
        end = "\r" if sys.stderr.isatty() else "\n"
        print(line, end=end, file=sys.stderr, flush=True)

    def report(self) -> dict[str, Any]:
        """The scenario's task and its score; for a scenario with no task, only what the robots did
        (collisions between them, the time), nothing about furniture."""
        score = self.world.score()
        task = self.world.scenario.task
        if task is None:
            return {"score": {k: score[k] for k in ROBOT_KEYS}}
        keys = [*SCORE_KEYS, *(k for k in MANY_TABLES_KEYS if k in score)]
        out: dict[str, Any] = {"task": task, "score": {k: score[k] for k in keys}}
        if len(self._table_starts) > 1:
            out["tables"] = self._tables()
        return out

    def close(self) -> list[str]:
        if self.progress_every and sys.stderr.isatty():
            print(file=sys.stderr)
        self.world.close()
        return [str(p) for p in self._outputs if p.exists()]
