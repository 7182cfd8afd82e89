"""The behaviour-test file (`*.test.yaml`) as a pydantic model: shape only; meaning is checked in check.py."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import ConfigDict, Discriminator, Field, StringConstraints, Tag

from hfsm.model import Name, Strict
from hfsm.names import NAME_PATTERN

ScopeName = Annotated[str, StringConstraints(pattern=rf"^{NAME_PATTERN[1:-1]}(/{NAME_PATTERN[1:-1]})*$")]

Seconds = Annotated[float, Field(ge=0, allow_inf_nan=False)]
StatePath = Annotated[str, StringConstraints(pattern=r"^[a-z][a-z0-9_]*(/[a-z][a-z0-9_]*)*$")]


class Step(Strict):
    """One call of a stand-in: it takes `after` seconds, then ends with `outcome` and `outputs`."""

    after: Seconds = Field(default=0, description="seconds the call takes (0: ends in the tick it began)")
    outcome: Name | None = Field(default=None, description="absent: the call never ends by itself")
    outputs: dict[Name, Any] = Field(default_factory=dict)
    doc: str | None = None


Script = Step | Annotated[list[Step], Field(min_length=1)]


class ByAgent(Strict):
    by_agent: dict[Name, Script] = Field(min_length=1, description="agent -> its own script")


def _stand_in_kind(value: Any) -> str:
    if isinstance(value, dict | ByAgent):
        return "by-agent" if (isinstance(value, ByAgent) or "by_agent" in value) else "step"
    return "steps" if isinstance(value, list) else "step"


StandIn = Annotated[
    Annotated[Step, Tag("step")]
    | Annotated[list[Step], Tag("steps"), Field(min_length=1)]
    | Annotated[ByAgent, Tag("by-agent")],
    Discriminator(_stand_in_kind),
]


class InputsAt(Strict):
    """Input values (`in.NAME`) that hold from time `at` on, for one agent or for all."""

    at: Seconds = 0
    agent: Name | None = Field(default=None, description="absent: every agent")
    in_: dict[Name, Any] = Field(alias="in", min_length=1, description="input name -> value")


class MessageIn(Strict):
    """A message that enters the mailboxes at time `at`, as if sent by agent `from`
    (docs/REFERENCE.md#messages-between-agents)."""

    at: Seconds = 0
    from_: Name = Field(alias="from", description="the sender: any name, in the run or not")
    message: Name
    to: Name | None = Field(default=None, description="absent: every agent of the test but the sender")
    data: dict[str, Any] = Field(default_factory=dict)
    scope: ScopeName | None = Field(
        default=None, description="sent under this scope, qualified: `pair_a` or `room/pair_a`"
    )

    @property
    def qualified(self) -> str:
        return f"{self.scope}/{self.message}" if self.scope else self.message


class FailAt(Strict):
    """An agent that fails at time `at` (docs/REFERENCE.md#agents-that-fail): it acts no more, sends nothing,
    hears nothing."""

    agent: Name
    at: Seconds
    reason: str = "scripted by the test"


class PartnerAt(Strict):
    """A scripted team mate outside the test that arrives at barrier `barrier` at time `at`
    (docs/REFERENCE.md#barriers):
    from then on it sends its notice to every agent of the test, as an agent waiting there does."""

    agent: Name = Field(description="its name: not an agent of the test")
    barrier: str | None = Field(
        default=None, min_length=1, description="the barrier's name (none: a team mate that never arrives)"
    )
    at: Seconds = 0


Level = Literal["off", "low", "high", "full"]


class OperatorAt(Strict):
    """A decision of the operator, as a record of `hfsm-run --operator FILE`."""

    t: Seconds = Field(
        description="when it takes effect: at the start of the tick a span of t s from tick 0 ends in"
    )
    agent: Name | None = Field(default=None, description="the agent answered (accept, force)")
    do: Literal["accept", "force", "autonomy", "pause", "resume", "step"]
    event: str | None = Field(default=None, description="force: the event taken; accept: the event held")
    level: Level | None = Field(default=None, description="autonomy: the run's new level")


class TimeRange(Strict):
    min: Seconds | None = None
    max: Seconds | None = None


Time = Seconds | TimeRange


class Sent(Strict):
    message: Name
    scope: ScopeName | None = Field(default=None, description="sent under this scope, qualified")
    to: Name | None = None
    data: dict[str, Any] | None = Field(default=None, description="these fields, with these values")
    at: Time | None = None


SentItem = Name | Sent


class Held(Strict):
    """An arc held for the operator: the state that held it, its event, the level it needed, when."""

    state: StatePath
    event: str = Field(description="an event of the state, `join:TARGET`, or a message")
    level: Level | None = None
    at: Time | None = None


class InOrderStates(Strict):
    in_order: list[StatePath] = Field(min_length=1, description="entered in this order, others between")


class InOrderSends(Strict):
    in_order: list[SentItem] = Field(min_length=1, description="sent in this order, others between")


class AgentExpect(Strict):
    outcome: Name | None = Field(default=None, description="null: the agent did not end")
    failed: bool | None = Field(
        default=None, description="whether the agent failed (docs/REFERENCE.md#agents-that-fail)")
    time: Time | None = Field(default=None, description="when its top machine ended (s)")
    outputs: dict[str, Any] | None = Field(default=None, description="these outputs, with these values")
    states: list[StatePath] | InOrderStates | None = Field(
        default=None, description="a list: exactly these, at their depths; in_order: a subsequence"
    )
    never: list[StatePath] | None = Field(default=None, description="states never entered")
    held: list[Held] | None = Field(default=None, description="exactly these arcs were held, in order")
    sends: list[SentItem] | InOrderSends | None = Field(
        default=None, description="a list: exactly these messages; in_order: a subsequence"
    )
    calls: dict[Name, Annotated[int, Field(ge=0)]] | None = Field(
        default=None, description="stand-in -> how many times it was called"
    )
    called_with: dict[Name, list[dict[Name, Any]]] | None = Field(
        default=None, description="stand-in -> the params of its first calls, one mapping a call (these keys)"
    )


class Expect(AgentExpect):
    """What every agent must do; `agents:` adds to it for each named agent."""

    error: str | None = Field(default=None, description="the run ends in an error containing this text")
    agents: dict[Name, AgentExpect] = Field(default_factory=dict)


class ScopeIn(Strict):
    """A scope the machine under test runs under, for the agents it lists, as if a caller's state
    had `scope:` (docs/REFERENCE.md#scopes)."""

    name: ScopeName = Field(description="its qualified name: `pair_t1`, or `room/pair_t1` for a nested one")
    agents: list[Name] = Field(min_length=1, description="its agents; each runs under it, leaving itself out")


class Setup(Strict):
    """What a case runs: given in the file for every case, or in a case, which then wins key by key."""

    machine: str | None = Field(default=None, description="a machine's name, or a path to its file")
    lib: list[str] | None = Field(default=None, description="more machine folders, from this file's")
    agents: list[Name] | None = Field(default=None, min_length=1, description="default: [robot]")
    params: dict[Name, Any] | None = None
    agent_params: dict[Name, dict[Name, Any]] | None = Field(
        default=None, description="agent -> params for that agent alone, over `params`"
    )
    seed: int | None = None
    dt: Annotated[float, Field(gt=0, allow_inf_nan=False)] | None = None
    max_time: Annotated[float, Field(gt=0, allow_inf_nan=False)] | None = None
    stand_ins: dict[Name, StandIn] | None = Field(default=None, description="behaviour -> its script")
    inputs: list[InputsAt] | None = None
    messages: list[MessageIn] | None = None
    fail: list[FailAt] | None = Field(default=None, description="agents that fail, and when")
    partners: list[PartnerAt] | None = Field(
        default=None, description="scripted team mates that arrive at barriers (each entry one round)"
    )
    scopes: list[ScopeIn] | None = Field(
        default=None, description="teams: each agent runs the machine under the scope that lists it"
    )
    autonomy: Level | None = Field(default=None, description="the run's autonomy level (default full)")
    operator: list[OperatorAt] | None = Field(default=None, description="the operator's decisions")


class VerifyCase(Strict):
    """Every run the world's choices allow (hfsm-verify), instead of one scripted run."""

    loss: Annotated[int, Field(ge=0)] = Field(default=0, description="messages or notices a run may lose")
    delay: Annotated[int, Field(ge=0)] = Field(default=0, description="ticks each may come late")
    fail: Annotated[int, Field(ge=0)] = Field(default=0, description="agents that may fail, at any tick")
    goal: Literal["success"] | None = Field(default=None, description="no agent that lives ends in a failure")
    bound: Annotated[float, Field(gt=0, allow_inf_nan=False)] | None = Field(
        default=None, description="run time explored (s); default: the top timer, else 600"
    )
    max_states: Annotated[int, Field(gt=0)] = Field(default=200_000, description="not proved past this")


class Case(Setup):
    doc: str | None = None
    expect: Expect | None = Field(default=None, description="what the run does (or give `verify`)")
    verify: VerifyCase | None = Field(default=None, description="prove the machine instead of one run")


class TestFile(Setup):
    """A behaviour-test file: a machine under test and its cases."""

    model_config = ConfigDict(title="hfsm behaviour test")
    __test__ = False  # not a pytest class

    doc: str | None = None
    tests: dict[Name, Case] = Field(min_length=1)
