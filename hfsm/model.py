"""The machine file as a pydantic model: data only, checked for shape; meaning is checked in checks/."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Discriminator, Field, StringConstraints, Tag

from hfsm.names import NAME_PATTERN

Name = Annotated[str, StringConstraints(pattern=NAME_PATTERN)]
Expr = Annotated[str, StringConstraints(pattern=r"^\$\{.*\}$")]
Timer = Annotated[float, Field(gt=0, allow_inf_nan=False)] | Expr
ParamType = Literal["int", "float", "bool", "str", "list", "dict"]


class Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True, populate_by_name=True)


class Param(Strict):
    type: ParamType
    default: Any = Field(default=None, description="no default means required")
    doc: str | None = None

    @property
    def required(self) -> bool:
        return "default" not in self.model_fields_set


class CallState(Strict):
    do: Name = Field(description="a built-in, a primitive or another machine")
    with_: dict[str, Any] = Field(default_factory=dict, alias="with")
    save: dict[Name, Name] = Field(default_factory=dict, description="var <- callee output")
    timer: Timer | None = None
    on: dict[Name, Name] = Field(default_factory=dict, description="event -> state or outcome")
    doc: str | None = None


class IfBranch(Strict):
    if_: str = Field(alias="if")
    then: Name
    doc: str | None = None


class ElseBranch(Strict):
    else_: Name = Field(alias="else")
    doc: str | None = None


def _branch_kind(value: Any) -> str:
    if isinstance(value, dict):
        return "else-branch" if "else" in value else "if-branch"
    return "else-branch" if isinstance(value, ElseBranch) else "if-branch"


Branch = Annotated[
    Annotated[IfBranch, Tag("if-branch")] | Annotated[ElseBranch, Tag("else-branch")],
    Discriminator(_branch_kind),
]


class ChoiceState(Strict):
    choose: list[Branch] = Field(min_length=1)
    doc: str | None = None


def _state_kind(value: Any) -> str:
    if isinstance(value, dict):
        return "choice-state" if "choose" in value else "call-state"
    return "choice-state" if isinstance(value, ChoiceState) else "call-state"


State = Annotated[
    Annotated[CallState, Tag("call-state")] | Annotated[ChoiceState, Tag("choice-state")],
    Discriminator(_state_kind),
]


class Machine(Strict):
    """One machine file. The machine's name is the file's stem."""

    model_config = ConfigDict(title="hfsm machine")

    name: Name | None = None
    doc: str | None = None
    params: dict[Name, Param] = Field(default_factory=dict)
    vars: dict[Name, Any] = Field(default_factory=dict)
    outcomes: list[Name] = Field(min_length=1)
    failures: list[Name] | None = None
    outputs: dict[Name, Any] = Field(default_factory=dict)
    receives: list[Name] = Field(default_factory=list)
    timer: Timer | None = None
    any: dict[Name, Name] = Field(default_factory=dict)
    initial: Name | None = None
    states: dict[Name, State] = Field(min_length=1)

    @property
    def initial_state(self) -> str:
        return self.initial or next(iter(self.states))

    @property
    def all_outcomes(self) -> list[str]:
        """Declared outcomes, plus `timeout` when the machine has a timer."""
        extra = ["timeout"] if self.timer is not None and "timeout" not in self.outcomes else []
        return [*self.outcomes, *extra]

    @property
    def failure_outcomes(self) -> frozenset[str]:
        if self.failures is not None:
            return frozenset(self.failures) | ({"timeout"} if self.timer is not None else set())
        return frozenset(o for o in self.all_outcomes if o in ("failure", "timeout"))
