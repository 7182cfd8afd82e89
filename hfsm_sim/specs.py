"""The parts of a scenario file: room, tables, targets, robot starts, batteries, failures.

Strict pydantic v2 models; `hfsm_sim.scenario.Scenario` puts them together and checks them against
each other (inside the room, known robots, unique ids).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Discriminator,
    Field,
    StringConstraints,
    Tag,
    ValidationError,
    model_validator,
)
from pydantic_core import InitErrorDetails, PydanticCustomError

RobotName = Annotated[str, StringConstraints(pattern=r"^[a-z][a-z0-9_]*$")]
TaskId = Annotated[str, StringConstraints(pattern=r"^[a-z][a-z0-9_]*$")]
Difficulty = Annotated[float, Field(gt=0.0, lt=1.0, description="TARARC's d_t, in the open interval (0, 1)")]


Refusal = tuple[tuple[int | str, ...], str, Any]  # where (keys below the model), why, the value


def refuse(title: str, refusals: list[Refusal]) -> None:
    """Raise every refusal at once, each at its own place (a file's reader shows its line)."""
    if refusals:
        raise ValidationError.from_exception_data(title, [
            InitErrorDetails(type=PydanticCustomError("refused", why), loc=loc, input=value)
            for loc, why, value in refusals])


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, allow_inf_nan=False)


class Room(Strict):
    width: float = Field(5.0, gt=1.5, le=50.0, description="extent along x, metres")
    depth: float = Field(5.0, gt=1.5, le=50.0, description="extent along y, metres")
    wall_height: float = Field(2.0, gt=0.3, le=5.0)


class TableSpec(Strict):
    id: TaskId | None = Field(None, description="the task's name (default table1, table2, ... in order)")
    x: float = 0.0
    y: float = 0.0
    yaw: float = Field(0.0, description="degrees, long side along x at 0")
    length: float = Field(0.8, gt=0.2, le=3.0)
    width: float = Field(0.5, gt=0.2, le=2.0)
    height: float = Field(0.33, ge=0.25, le=0.40, description="floor to top surface")
    mass: float = Field(2.0, gt=0.1, le=20.0)
    difficulty: Difficulty = 0.5
    priority: int = Field(1, ge=1, description="smaller is allocated first")

    @model_validator(mode="after")
    def _long_side_is_length(self) -> TableSpec:
        if self.width > self.length:
            why = (f"'width' must be <= the length, {self.length:g} (length is the long side), "
                   f"not {self.width:g}")
            refuse("TableSpec", [(("width",), why, self.width)])
        return self


class Target(Strict):
    """A point task of the allocation experiments (the paper's 'invader' to encircle)."""

    id: TaskId
    x: float
    y: float
    difficulty: Difficulty = 0.5
    priority: int = Field(1, ge=1, description="smaller is allocated first")


class LinearBattery(Strict):
    """A charge, 0..1, that time, walking and reading messages use up; empty, the robot fails."""

    model: Literal["linear"] = "linear"
    start: float = Field(1.0, gt=0.0, le=1.0, description="charge at t = 0")
    idle: float = Field(0.0002, ge=0.0, le=1.0, description="charge spent per second")
    walk: float = Field(0.002, ge=0.0, le=1.0, description="charge spent per metre walked")
    read: float = Field(0.0, ge=0.0, le=1.0, description="charge spent per radio message read")


class Eq5Battery(Strict):
    """TARARC eq. 5 as docs/TARARC.md bounds it: S = w_tim (1+tim/tim_unit)^m + w_dist (1+dist/dist_unit)^n
    + w_sped (1+sped/sped_unit)^t, with tim the messages read, dist the distance from the start
    (m) and sped the mean speed since the start (m/s). The robot fails when S <= `empty`."""

    model: Literal["eq5"]
    w_tim: float = Field(1 / 3, ge=0.0, le=1.0)
    w_dist: float = Field(1 / 3, ge=0.0, le=1.0)
    w_sped: float = Field(1 / 3, ge=0.0, le=1.0)
    m: float = Field(-0.5, lt=0.0)
    n: float = Field(-0.5, lt=0.0)
    t: float = Field(-0.5, lt=0.0)
    tim_unit: float = Field(1.0, gt=0.0, description="messages counted as one 'tim'")
    dist_unit: float = Field(1.0, gt=0.0, description="metres counted as one 'dist'")
    sped_unit: float = Field(1.0, gt=0.0, description="m/s counted as one 'sped'")
    empty: float = Field(0.0, ge=0.0, lt=1.0, description="the robot fails at or below this energy")

    @model_validator(mode="after")
    def _weights_sum_to_one(self) -> Eq5Battery:
        total = self.w_tim + self.w_dist + self.w_sped
        if abs(total - 1.0) > 1e-9:
            raise ValueError(f"eq. 5 weights w_tim + w_dist + w_sped must sum to 1, not {total:g} "
                             f"({self.w_tim:g} + {self.w_dist:g} + {self.w_sped:g})")
        return self


def _battery_model(data: Any) -> str:
    if isinstance(data, dict):
        return f"battery-{data.get('model', 'linear')}"
    return f"battery-{getattr(data, 'model', 'linear')}"


BatterySpec = Annotated[
    Annotated[LinearBattery, Tag("battery-linear")] | Annotated[Eq5Battery, Tag("battery-eq5")],
    Discriminator(_battery_model),
]


class RobotStart(Strict):
    x: float
    y: float
    yaw: float = Field(0.0, description="degrees, 0 faces +x")
    body: Literal["full", "light"] = Field(
        "full", description="full: the humanoid with head cameras and arms; light: a camera-less cylinder")
    speed: float | None = Field(None, gt=0.0, le=3.0, description="top speed, m/s (default: the body's)")
    battery: BatterySpec | None = Field(None, description="this robot's battery (default: the scenario's)")


class RadioSpec(Strict):
    """The room's radio, when the scenario sets it (a run's own `radio_loss` wins when given)."""

    loss: float = Field(0.0, ge=0.0, le=0.9, description="chance that a message is lost, 0 to 0.9")


class Jitter(Strict):
    position: float = Field(0.0, ge=0.0, le=1.0, description="max offset per axis, metres")
    yaw: float = Field(0.0, ge=0.0, le=180.0, description="max offset, degrees")


class FailureAt(Strict):
    """A robot that fails (stops, drops what it holds, goes silent) at a time of the run."""

    robot: RobotName
    at: float = Field(ge=0.0, allow_inf_nan=False, description="seconds into the run")
    reason: str = "failed"


class FailureRate(Strict):
    """Robots that fail at random, each after an exponential time of mean 60/rate seconds drawn
    from the run's seed (so a seed fails the same robots at the same times)."""

    rate: float = Field(gt=0.0, le=60.0, description="failures per robot per minute")
    robots: list[RobotName] | None = Field(None, description="the robots at risk (default: all)")
    reason: str = "failed at random"


def _failure_kind(data: Any) -> str:
    if isinstance(data, dict):
        return "failure-rate" if "rate" in data else "failure-at"
    return "failure-rate" if isinstance(data, FailureRate) else "failure-at"


FailureSpec = Annotated[
    Annotated[FailureAt, Tag("failure-at")] | Annotated[FailureRate, Tag("failure-rate")],
    Discriminator(_failure_kind),
]
