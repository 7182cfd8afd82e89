"""Scenario files: room, tables and targets, robot starts, batteries and failures, as a strict
pydantic v2 model (the parts are in hfsm_sim/specs.py).

The engine reads YAML itself (with line:col errors) and passes the parsed mapping to
`scenario_from_dict`; `load_scenario` is a plain `yaml.safe_load` convenience.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Any, Literal

import numpy as np
import yaml
from pydantic import Field, ValidationInfo, field_validator, model_validator
from pydantic_core import PydanticCustomError

from hfsm_sim.specs import (
    BatterySpec,
    Eq5Battery,
    FailureAt,
    FailureRate,
    FailureSpec,
    Jitter,
    LinearBattery,
    RadioSpec,
    Refusal,
    RobotName,
    RobotStart,
    Room,
    Strict,
    TableSpec,
    Target,
    refuse,
)

__all__ = [
    "DEFAULT_SCENARIO",
    "BatterySpec",
    "Eq5Battery",
    "FailureAt",
    "FailureRate",
    "FailureSpec",
    "Jitter",
    "LinearBattery",
    "RadioSpec",
    "RobotStart",
    "Room",
    "Scenario",
    "TableSpec",
    "Target",
    "load_scenario",
    "resolve",
    "scenario_from_dict",
    "scenario_names",
]

DEFAULT_SCENARIO = "opposite_long_side"
Task = Literal["table_to_wall"]  # what a run is scored on (hfsm_sim.scorer): the paper's task
MAX_ROBOTS, MAX_FULL_ROBOTS = 50, 16
WALL_CLEARANCE = 0.2


class Scenario(Strict):
    description: str = ""
    task: Task | None = Field(None, description="what the run is scored on; absent: nothing")
    room: Room = Room()
    table: TableSpec | None = Field(None, description="one table (shorthand for a one-item `tables:`)")
    tables: list[TableSpec] | None = None
    targets: list[Target] = Field(default_factory=list)
    robots: dict[RobotName, RobotStart] = Field(min_length=1, max_length=MAX_ROBOTS)
    jitter: Jitter = Jitter()
    battery: BatterySpec = LinearBattery()
    failures: list[FailureSpec] = Field(default_factory=list)
    radio: RadioSpec = Field(default_factory=RadioSpec, description="the room's radio loss")

    @field_validator("robots")
    @classmethod
    def _few_full_bodies(cls, robots: dict[str, RobotStart]) -> dict[str, RobotStart]:
        full = sum(start.body == "full" for start in robots.values())
        if full > MAX_FULL_ROBOTS:
            message = f"{full} robots with the full body; at most {MAX_FULL_ROBOTS} (use body: light)"
            raise PydanticCustomError("too_many_full", message)
        return robots

    @field_validator("failures")
    @classmethod
    def _known_robots(cls, failures: list[FailureAt | FailureRate], info: ValidationInfo
                      ) -> list[FailureAt | FailureRate]:
        if "robots" not in info.data:
            return failures  # the robots are refused themselves: which names exist is not known
        robots = info.data["robots"]
        refusals: list[Refusal] = []
        for i, failure in enumerate(failures):
            named = [(("robot",), failure.robot)] if isinstance(failure, FailureAt) else [
                (("robots", k), name) for k, name in enumerate(failure.robots or [])]
            known = ", ".join(robots)
            refusals += [((i, *at), f"no robot named '{name}' in the scenario (robots: {known})", name)
                         for at, name in named if name not in robots]
        refuse("failures", refusals)
        return failures

    @model_validator(mode="after")
    def _consistent(self) -> Scenario:
        """Tables, targets and robots in the room, unique task ids: every problem at its value."""
        refusals: list[Refusal] = []
        if self.table is not None and self.tables is not None:
            both = "give either `table:` (one table) or `tables:` (a list), not both"
            refusals.append((("tables",), both, None))
        ids = self.task_ids()
        places: list[tuple[int | str, ...]] = [("tables", i) if self.tables is not None else ("table",)
                                               for i in range(len(self.all_tables))]
        places += [("targets", j) for j in range(len(self.targets))]
        unique = "ids must be unique across tables and targets"
        refusals += [((*at, "id"), f"task id '{i}' is used before: {unique}", i)
                     for k, (at, i) in enumerate(zip(places, ids, strict=True)) if i in ids[:k]]
        room = f"{self.room.width:g} x {self.room.depth:g} m"
        for at, t in zip(places, self.all_tables, strict=False):
            c, s = abs(math.cos(math.radians(t.yaw))), abs(math.sin(math.radians(t.yaw)))
            reach = {"x": (c * t.length + s * t.width) / 2, "y": (s * t.length + c * t.width) / 2}
            refusals += _outside(at, t, reach, self.room, f"for the table ({t.length:g} x {t.width:g} m, yaw "
                                 f"{t.yaw:g}) to fit inside the room ({room})")
        for j, target in enumerate(self.targets):
            refusals += _outside(("targets", j), target, {"x": 0.0, "y": 0.0}, self.room,
                                 f"inside the room ({room})")
        slack = self.jitter.position  # the seeded jitter may move a start this far either way
        for name, start in self.robots.items():
            reach = {"x": WALL_CLEARANCE + slack, "y": WALL_CLEARANCE + slack}
            refusals += _outside(("robots", name), start, reach, self.room,
                                 f"for the robot to start inside the room ({room}) {WALL_CLEARANCE:g} m "
                                 f"from its walls, with {slack:g} m of jitter")
        refuse("Scenario", refusals)
        return self

    @property
    def all_tables(self) -> list[TableSpec]:
        """The tables of the room: `tables:`, or the one `table:`, or the default table when neither
        is given (the scenarios of the paper); `tables: []` is a room without tables."""
        if self.tables is not None:
            return list(self.tables)
        return [self.table or TableSpec()]

    def table_ids(self) -> list[str]:
        return [t.id or f"table{i + 1}" for i, t in enumerate(self.all_tables)]

    def task_ids(self) -> list[str]:
        return [*self.table_ids(), *(t.id for t in self.targets)]

    def tasks(self) -> list[dict[str, Any]]:
        """The tasks the team is given (tables at their start, then targets), as plain data."""
        tables: list[tuple[str, str, TableSpec | Target]] = [
            (i, "table", t) for i, t in zip(self.table_ids(), self.all_tables, strict=True)]
        targets: list[tuple[str, str, TableSpec | Target]] = [(t.id, "target", t) for t in self.targets]
        out: list[dict[str, Any]] = []
        for i, kind, t in [*tables, *targets]:
            task: dict[str, Any] = {"id": i, "kind": kind, "x": t.x, "y": t.y, "difficulty": t.difficulty,
                                    "priority": t.priority}
            if isinstance(t, TableSpec):
                task.update(yaw=t.yaw, length=t.length, width=t.width)
            out.append(task)
        return out

    def told_start(self, name: str) -> dict[str, float]:
        """Where robot `name` is told it was placed: its start as written (yaw in degrees), not the
        jittered truth."""
        start = self.robots[name]
        return {"x": start.x, "y": start.y, "yaw": start.yaw}

    def battery_of(self, name: str) -> LinearBattery | Eq5Battery:
        return self.robots[name].battery or self.battery

    def starts(self, seed: int) -> dict[str, tuple[float, float, float]]:
        """Robot start poses (x, y, yaw radians) with the seeded jitter applied, in order."""
        rng = np.random.default_rng([seed, 0x5CE])
        poses: dict[str, tuple[float, float, float]] = {}
        for name, start in self.robots.items():
            dx, dy = rng.uniform(-1.0, 1.0, 2) * self.jitter.position
            dyaw = rng.uniform(-1.0, 1.0) * self.jitter.yaw
            poses[name] = (start.x + dx, start.y + dy, math.radians(start.yaw + dyaw))
        return poses

    def failure_times(self, seed: int) -> list[tuple[float, str, str]]:
        """(seconds, robot, reason) of every failure the scenario schedules for this seed, in file
        order: the `at:` ones as written, and for each `rate:` entry an exponential time to failure
        per robot at risk (in scenario order), drawn from the seed. A robot fails once: only its
        earliest failure is kept."""
        due: list[tuple[float, str, str]] = []
        for i, failure in enumerate(self.failures):
            if isinstance(failure, FailureAt):
                due.append((failure.at, failure.robot, failure.reason))
                continue
            rng = np.random.default_rng([seed, 0xFA11, i])
            for name in failure.robots or list(self.robots):
                due.append((float(rng.exponential(60.0 / failure.rate)), name, failure.reason))
        earliest: dict[str, tuple[float, str, str]] = {}
        for item in due:
            if item[1] not in earliest or item[0] < earliest[item[1]][0]:
                earliest[item[1]] = item
        return [item for item in due if earliest[item[1]] is item]


def _outside(at: tuple[int | str, ...], thing: Any, reach: dict[str, float], room: Room, why: str
             ) -> list[Refusal]:
    """`x` and `y` of a thing that reaches `reach` metres either way: those that leave the room."""
    out: list[Refusal] = []
    for axis, half in (("x", room.width / 2), ("y", room.depth / 2)):
        value, most = getattr(thing, axis), half - reach[axis]
        if abs(value) > most + 1e-9:
            allowed = f"from {-most:g} to {most:g}" if most >= 0 else "impossible: it is too large"
            out.append(((*at, axis), f"'{axis}' must be {allowed} {why}, not {value:g}", value))
    return out


def scenario_from_dict(data: Mapping[str, Any]) -> Scenario:
    """Validate already-parsed scenario data (raises pydantic.ValidationError)."""
    return Scenario.model_validate(dict(data))


def scenario_names() -> list[str]:
    """Names of the scenarios shipped in hfsm_sim/scenarios/."""
    folder = resources.files("hfsm_sim") / "scenarios"
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".yaml"))


def resolve(name_or_path: str | Path) -> Path:
    """A shipped scenario name ("ahead_behind") or a path to a YAML file -> existing path."""
    text = str(name_or_path)
    looks_like_path = Path(text).suffix in {".yaml", ".yml"} or "/" in text or "\\" in text
    if looks_like_path:
        path = Path(text)
        if not path.is_file():
            raise FileNotFoundError(f"scenario file not found: {text}")
        return path
    shipped = Path(str(resources.files("hfsm_sim") / "scenarios" / f"{text}.yaml"))
    if shipped.is_file():
        return shipped
    names = scenario_names()
    close = difflib.get_close_matches(text, names, n=1)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    raise FileNotFoundError(f"unknown scenario {text!r}{hint} (shipped: {', '.join(names)})")


def load_scenario(name_or_path: str | Path = DEFAULT_SCENARIO) -> Scenario:
    """Resolve, read with yaml.safe_load and validate."""
    with resolve(name_or_path).open(encoding="utf-8") as handle:
        return scenario_from_dict(yaml.safe_load(handle) or {})
