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


# a bare expression, or a YAML literal (docs/REFERENCE.md#expressions)
Condition = str | bool | int | float | None


def condition_text(value: Condition) -> str:
    """A condition as expression text: a YAML literal (`true`, `null`, `3`) reads as that literal."""
    if isinstance(value, str):
        return value
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value)


Path = tuple[str, ...]
Count = Annotated[int, Field(gt=0)] | Expr
Delay = Annotated[float, Field(ge=0, allow_inf_nan=False)] | Expr


class Watch(Strict):
    """A condition tried on entry and every tick (docs/REFERENCE.md#watches)."""

    if_: Condition = Field(alias="if")
    then: Name
    doc: str | None = None

    @property
    def condition(self) -> str:
        return condition_text(self.if_)


class Retry(Strict):
    """Call the behaviour again when it ends with one of these outcomes (docs/REFERENCE.md#retries)."""

    on: list[Name] = Field(min_length=1, description="outcomes of the callee, or `error`")
    times: Count = Field(description="retries after the first call: a positive int or ${params...}")
    delay: Delay = Field(default=0, description="seconds between an end and the next call")


class ScopeSpec(Strict):
    """A team within the team for what the state runs: a private radio with these agents."""

    name: str = Field(description="a name, or an expression giving one; qualified inside an outer scope")
    agents: list[Any] | str = Field(description="agent ids of the enclosing scope, or an expression of them")


class CallState(Strict):
    do: Name = Field(description="a built-in, a primitive or another machine")
    with_: dict[str, Any] = Field(default_factory=dict, alias="with")
    save: dict[Name, Name] = Field(default_factory=dict, description="var <- callee output")
    timer: Timer | None = None
    on: dict[Name, Name] = Field(default_factory=dict, description="event -> state or outcome")
    watch: list[Watch] = Field(default_factory=list)
    retry: Retry | None = None
    scope: ScopeSpec | None = None
    autonomy: dict[str, str] = Field(
        default_factory=dict, description="event -> level (off, low, high, full) below which its arc is held"
    )
    doc: str | None = None


class Region(Strict):
    """One behaviour of a parallel state (docs/REFERENCE.md#parallel-states)."""

    do: Name = Field(description="a built-in, a primitive or another machine")
    with_: dict[str, Any] = Field(default_factory=dict, alias="with")
    save: dict[Name, Name] = Field(default_factory=dict, description="var <- callee output")
    background: bool = Field(default=False, description="never awaited; cancelled when the state is left")
    doc: str | None = None


class JoinRule(Strict):
    when: dict[Name, Name | list[Name]] = Field(min_length=1, description="region -> outcome(s)")
    then: Name
    doc: str | None = None


class JoinElse(Strict):
    else_: Name = Field(alias="else")
    doc: str | None = None


def _join_kind(value: Any) -> str:
    if isinstance(value, dict):
        return "join-else" if "else" in value and "when" not in value else "join-rule"
    return "join-else" if isinstance(value, JoinElse) else "join-rule"


JoinBranch = Annotated[
    Annotated[JoinRule, Tag("join-rule")] | Annotated[JoinElse, Tag("join-else")],
    Discriminator(_join_kind),
]


class ParallelState(Strict):
    parallel: dict[Name, Region] = Field(min_length=1, description="regions, started in this order")
    join: list[JoinBranch] = Field(min_length=1, description="rules tried in order; `else` may end it")
    timer: Timer | None = None
    on: dict[Name, Name] = Field(default_factory=dict, description="event -> state or outcome")
    watch: list[Watch] = Field(default_factory=list)
    scope: ScopeSpec | None = None
    autonomy: dict[str, str] = Field(
        default_factory=dict, description="event or join:TARGET -> level below which its arc is held"
    )
    doc: str | None = None


def state_calls(name: str, state: CallState | ChoiceState | ParallelState) -> list[tuple[Path, str]]:
    """What a state calls, each with the path of its `do` key (a parallel state: each region's)."""
    if isinstance(state, CallState):
        return [(("states", name, "do"), state.do)]
    if isinstance(state, ParallelState):
        return [(("states", name, "parallel", r, "do"), reg.do) for r, reg in state.parallel.items()]
    return []


class IfBranch(Strict):
    if_: Condition = Field(alias="if")
    then: Name
    doc: str | None = None

    @property
    def condition(self) -> str:
        return condition_text(self.if_)


class ElseBranch(Strict):
    else_: Name = Field(alias="else")
    doc: str | None = None


def _branch_kind(value: Any) -> str:
    if isinstance(value, dict):
        return "else-branch" if "else" in value and "if" not in value else "if-branch"
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
        if "choose" in value:
            return "choice-state"
        return "parallel-state" if "parallel" in value else "call-state"
    if isinstance(value, ChoiceState):
        return "choice-state"
    return "parallel-state" if isinstance(value, ParallelState) else "call-state"


State = Annotated[
    Annotated[CallState, Tag("call-state")]
    | Annotated[ChoiceState, Tag("choice-state")]
    | Annotated[ParallelState, Tag("parallel-state")],
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
    untraced: list[Name] = Field(
        default_factory=list, description="vars the trace does not show (large values that change often)"
    )
    receives: list[Name] = Field(default_factory=list)
    timer: Timer | None = None
    any: dict[Name, Name] = Field(default_factory=dict)
    watch: list[Watch] = Field(default_factory=list, description="tried in every call and parallel state")
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
