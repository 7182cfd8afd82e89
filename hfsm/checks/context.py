"""What every check reads: the loaded machines, the behaviours they may call, and where things stand."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, replace
from functools import cached_property

from hfsm import digraph
from hfsm.builtins import BUILTINS
from hfsm.errors import Finding, Severity
from hfsm.graph import call_graph
from hfsm.library import MachineFile
from hfsm.model import CallState, ChoiceState, Machine, ParallelState
from hfsm.registry import Registry
from hfsm.scalarpos import inside_string
from hfsm.spec import BehaviourSpec, ParamSpec
from hfsm.world import InputSpec
from hfsm.yamlio import Path_


def machine_spec(machine: MachineFile) -> BehaviourSpec:
    m = machine.model
    params = {
        name: ParamSpec(name, p.type, p.required, p.default, p.doc or "") for name, p in m.params.items()
    }
    return BehaviourSpec(
        machine.name,
        "machine",
        params,
        tuple(m.all_outcomes),
        m.failure_outcomes,
        frozenset(m.outputs),
        m.doc or "",
    )


@dataclass
class CheckContext:
    machines: dict[str, MachineFile]
    registry: Registry
    inputs: Mapping[str, InputSpec] | None = None  # what the run's world declares; None: not known
    findings: list[Finding] = field(default_factory=list)
    memo: dict[tuple[str, str], object] = field(default_factory=dict)  # what checks share, by (kind, name)

    @cached_property
    def specs(self) -> dict[str, BehaviourSpec]:
        specs = dict(BUILTINS)
        specs.update({p.spec.name: p.spec for p in self.registry})
        specs.update({name: machine_spec(m) for name, m in self.machines.items()})
        return specs

    @cached_property
    def calls(self) -> digraph.DiGraph:
        """Who calls whom, among the loaded machines and what they call."""
        return call_graph({name: m.model for name, m in self.machines.items()})

    def error(
        self,
        machine: MachineFile,
        path: Path_,
        code: str,
        message: str,
        *,
        key: bool = False,
        span: tuple[int, int] | None = None,
    ) -> None:
        """A finding at the key or value at `path`; `span`: the offsets of the characters at fault
        inside the string value there (the finding stays at the string's start if they cannot be
        placed exactly)."""
        found = machine.doc.finding(path, code, message, key=key)
        self.findings.append(inside_string(machine.doc, path, found, span) if span and not key else found)

    def warn(self, machine: MachineFile, path: Path_, code: str, message: str, *, key: bool = False) -> None:
        f = machine.doc.finding(path, code, message, key=key)
        self.findings.append(replace(f, severity=Severity.WARNING))


def call_states(m: Machine) -> Iterator[tuple[str, CallState]]:
    for name, state in m.states.items():
        if isinstance(state, CallState):
            yield name, state


def choice_states(m: Machine) -> Iterator[tuple[str, ChoiceState]]:
    for name, state in m.states.items():
        if isinstance(state, ChoiceState):
            yield name, state


def parallel_states(m: Machine) -> Iterator[tuple[str, ParallelState]]:
    for name, state in m.states.items():
        if isinstance(state, ParallelState):
            yield name, state
