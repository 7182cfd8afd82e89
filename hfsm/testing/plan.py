"""A checked test case, ready to run: every name resolved, every value where the file put it."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from hfsm.autonomy import Decision
from hfsm.load import Loaded
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec
from hfsm.testing.model import Expect, FailAt, InputsAt, MessageIn, PartnerAt, Step, VerifyCase
from hfsm.yamlio import Document, Path_


@dataclass(frozen=True)
class StandInPlan:
    """A behaviour replaced by a script: one list of steps for every agent, or one per agent."""

    spec: BehaviourSpec
    scripts: dict[str | None, list[Step]]  # agent (None: any other agent) -> steps, one per call

    def steps_for(self, agent: str) -> list[Step] | None:
        return self.scripts.get(agent, self.scripts.get(None))


@dataclass
class CasePlan:
    file: str  # as shown to users
    name: str
    doc: Document
    path: Path_  # of the case in the document
    loaded: Loaded
    registry: Registry  # every primitive installed, of every world
    top: str
    agents: list[str]
    params: dict[str, Any]
    agent_params: dict[str, dict[str, Any]]  # agent -> its params, for those `agent_params` names
    seed: int
    dt: float
    max_time: float
    stand_ins: dict[str, StandInPlan]
    inputs: list[tuple[InputsAt, Path_]]
    messages: list[tuple[MessageIn, Path_]]
    fail: list[FailAt]
    partners: list[PartnerAt]
    autonomy: str
    decisions: list[Decision]
    expect: Expect
    expect_path: Path_
    pruned: set[str] = field(default_factory=set)  # machines not run: only stand-ins call them
    verify: VerifyCase | None = None  # every run the world's choices allow, instead of one
    scopes: dict[str, tuple[str, tuple[str, ...]]] = field(default_factory=dict)  # agent -> its scope

    @property
    def line(self) -> int:
        return self.doc.pos(self.path, key=True)[0]
