"""Scenario files: room, table and robot starts, as a strict pydantic v2 model.

The engine reads YAML itself (with line:col errors) and passes the parsed mapping to
`scenario_from_dict`; `load_scenario` is a plain `yaml.safe_load` convenience.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
import yaml
from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    StringConstraints,
    ValidationInfo,
    field_validator,
    model_validator,
)
from pydantic_core import PydanticCustomError

DEFAULT_SCENARIO = "opposite_long_side"
Task = Literal["table_to_wall"]  # what a run is scored on (sim.scorer): the paper's task
RobotName = Annotated[str, StringConstraints(pattern=r"^[a-z][a-z0-9_]*$")]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, allow_inf_nan=False)


class Room(_Strict):
    width: float = Field(5.0, gt=1.5, le=50.0, description="extent along x, metres")
    depth: float = Field(5.0, gt=1.5, le=50.0, description="extent along y, metres")
    wall_height: float = Field(2.0, gt=0.3, le=5.0)


class TableSpec(_Strict):
    x: float = 0.0
    y: float = 0.0
    yaw: float = Field(0.0, description="degrees, long side along x at 0")
    length: float = Field(0.8, gt=0.2, le=3.0)
    width: float = Field(0.5, gt=0.2, le=2.0)
    height: float = Field(0.33, ge=0.25, le=0.40, description="floor to top surface")
    mass: float = Field(2.0, gt=0.1, le=20.0)

    @model_validator(mode="after")
    def _long_side_is_length(self) -> TableSpec:
        if self.width > self.length:
            raise ValueError("table width must not exceed its length (length is the long side)")
        return self


class RobotStart(_Strict):
    x: float
    y: float
    yaw: float = Field(0.0, description="degrees, 0 faces +x")


class Jitter(_Strict):
    position: float = Field(0.0, ge=0.0, le=1.0, description="max offset per axis, metres")
    yaw: float = Field(0.0, ge=0.0, le=180.0, description="max offset, degrees")


class Battery(_Strict):
    """A robot's charge, 0..1: it falls with time and with the distance walked; empty, it fails."""

    start: float = Field(1.0, gt=0.0, le=1.0, description="charge at t = 0")
    idle: float = Field(0.0002, ge=0.0, le=1.0, description="charge spent per second")
    walk: float = Field(0.002, ge=0.0, le=1.0, description="charge spent per metre walked")


class FailureSpec(_Strict):
    """A robot that fails (stops, drops what it holds, goes silent) at a time of the run."""

    robot: RobotName
    at: float = Field(ge=0.0, allow_inf_nan=False, description="seconds into the run")
    reason: str = "failed"


class Scenario(_Strict):
    description: str = ""
    task: Task | None = Field(None, description="what the run is scored on; absent: nothing")
    room: Room = Room()
    table: TableSpec = TableSpec()
    robots: dict[RobotName, RobotStart] = Field(min_length=1, max_length=5)
    jitter: Jitter = Jitter()
    battery: Battery = Battery()
    failures: list[FailureSpec] = []

    @field_validator("failures")
    @classmethod
    def _known_robots(cls, failures: list[FailureSpec], info: ValidationInfo) -> list[FailureSpec]:
        robots = info.data.get("robots") or {}
        for i, failure in enumerate(failures):
            if failure.robot not in robots:
                names = ", ".join(robots)
                raise PydanticCustomError("unknown_robot", f"[{i}] names no robot of the scenario ({names})")
        return failures

    @model_validator(mode="after")
    def _inside_room(self) -> Scenario:
        half_w, half_d = self.room.width / 2, self.room.depth / 2
        t = self.table
        c, s = abs(math.cos(math.radians(t.yaw))), abs(math.sin(math.radians(t.yaw)))
        reach_x, reach_y = (c * t.length + s * t.width) / 2, (s * t.length + c * t.width) / 2
        if abs(t.x) + reach_x > half_w + 1e-9 or abs(t.y) + reach_y > half_d + 1e-9:
            raise ValueError("table does not fit inside the room")
        slack = self.jitter.position  # the seeded jitter may move a start this far either way
        for name, start in self.robots.items():
            if abs(start.x) + slack > half_w - 0.2 or abs(start.y) + slack > half_d - 0.2:
                raise ValueError(f"robot {name!r} could start outside the room or inside a wall")
        return self

    def starts(self, seed: int) -> dict[str, tuple[float, float, float]]:
        """Robot start poses (x, y, yaw radians) with the seeded jitter applied, in order."""
        rng = np.random.default_rng([seed, 0x5CE])
        poses: dict[str, tuple[float, float, float]] = {}
        for name, start in self.robots.items():
            dx, dy = rng.uniform(-1.0, 1.0, 2) * self.jitter.position
            dyaw = rng.uniform(-1.0, 1.0) * self.jitter.yaw
            poses[name] = (start.x + dx, start.y + dy, math.radians(start.yaw + dyaw))
        return poses


def scenario_from_dict(data: Mapping[str, Any]) -> Scenario:
    """Validate already-parsed scenario data (raises pydantic.ValidationError)."""
    return Scenario.model_validate(dict(data))


def scenario_names() -> list[str]:
    """Names of the scenarios shipped in sim/scenarios/."""
    folder = resources.files("sim") / "scenarios"
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
    shipped = Path(str(resources.files("sim") / "scenarios" / f"{text}.yaml"))
    if shipped.is_file():
        return shipped
    raise FileNotFoundError(f"unknown scenario {text!r}; shipped: {', '.join(scenario_names())}")


def load_scenario(name_or_path: str | Path = DEFAULT_SCENARIO) -> Scenario:
    """Resolve, read with yaml.safe_load and validate."""
    with resolve(name_or_path).open(encoding="utf-8") as handle:
        return scenario_from_dict(yaml.safe_load(handle) or {})
