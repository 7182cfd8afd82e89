"""Check a case's expectations against the machines: a misspelt state or outcome would never match."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Protocol

from hfsm.load import Loaded
from hfsm.model import CallState, Machine, ParallelState
from hfsm.names import did_you_mean
from hfsm.testing.model import AgentExpect, Expect, InOrderStates
from hfsm.testing.plan import StandInPlan
from hfsm.yamlio import Path_


class Reporter(Protocol):
    def error(self, path: Path_, code: str, message: str, *, key: bool = False) -> None: ...


def check_expect(
    out: Reporter,
    loaded: Loaded,
    stand_ins: Mapping[str, StandInPlan],
    expect: Expect,
    at: Path_,
    agents: set[str],
) -> Expect:
    models = {n: m.model for n, m in loaded.machines.items()}
    top = loaded.roots[0]
    _agent(out, models, top.name, stand_ins, expect, at)
    for name, each in expect.agents.items():
        where = (*at, "agents", name)
        if name not in agents:
            hint = did_you_mean(name, agents) or f" (agents: {', '.join(sorted(agents))})"
            out.error(where, "T320", f"no agent '{name}' in this test{hint}", key=True)
        _agent(out, models, top.name, stand_ins, each, where)
    return expect


def _agent(
    out: Reporter,
    models: Mapping[str, Machine],
    top: str,
    stand_ins: Mapping[str, StandInPlan],
    expect: AgentExpect,
    at: Path_,
) -> None:
    machine = models[top]
    if expect.outcome is not None and expect.outcome not in machine.all_outcomes:
        hint = (
            did_you_mean(expect.outcome, machine.all_outcomes)
            or f" (it has: {', '.join(machine.all_outcomes)})"
        )
        out.error((*at, "outcome"), "T321", f"'{top}' has no outcome '{expect.outcome}'{hint}")
    for name in expect.outputs or {}:
        if name not in machine.outputs:
            hint = did_you_mean(name, machine.outputs) or f" (it has: {', '.join(machine.outputs) or 'none'})"
            out.error((*at, "outputs", name), "T321", f"'{top}' has no output '{name}'{hint}", key=True)
    states = expect.states.in_order if isinstance(expect.states, InOrderStates) else expect.states
    listed = "states" if not isinstance(expect.states, InOrderStates) else "states/in_order"
    for key, paths in ((listed, states), ("never", expect.never)):
        for i, path in enumerate(paths or []):
            problem = path_problem(models, top, set(stand_ins), path)
            if problem:
                out.error((*at, *key.split("/"), i), "T322", problem)
    for i, held in enumerate(expect.held or []):
        problem = path_problem(models, top, set(stand_ins), held.state)
        if problem:
            out.error((*at, "held", i, "state"), "T322", problem)
    counted = [("calls", n) for n in expect.calls or {}] + [
        ("called_with", n) for n in expect.called_with or {}
    ]
    for key, name in counted:
        if name not in stand_ins:
            known = ", ".join(sorted(stand_ins)) or "none here"
            hint = did_you_mean(name, stand_ins) or f" (stand-ins: {known})"
            out.error(
                (*at, key, name),
                "T323",
                f"calls are recorded for stand-ins only: '{name}' is not one{hint}",
                key=True,
            )


def path_problem(models: Mapping[str, Machine], top: str, stand_ins: set[str], path: str) -> str:
    """Why `a/b/c` (states from the top machine down, a region's name after a parallel state) cannot be
    entered; '' when it can."""
    machine, name = models[top], top
    parts = path.split("/")
    i = 0
    while i < len(parts):
        part = parts[i]
        state = machine.states.get(part)
        if state is None:
            return f"'{name}' has no state '{part}'{did_you_mean(part, machine.states)}"
        i += 1
        if i == len(parts):
            return ""
        callee = ""  # a choice state calls nothing
        if isinstance(state, ParallelState):
            region = state.parallel.get(parts[i])
            if region is None:
                return f"'{part}' has no region '{parts[i]}'{did_you_mean(parts[i], state.parallel)}"
            callee, i = region.do, i + 1
            if i == len(parts):
                return ""
        elif isinstance(state, CallState):
            callee = state.do
        if callee in stand_ins:
            return f"'{callee}' is stood in for: no state below '{'/'.join(parts[:i])}' is entered"
        if callee not in models:
            what = f"calls '{callee}', which has no states" if callee else "is a choice: nothing is below it"
            return f"'{'/'.join(parts[:i])}' {what}"
        machine, name = models[callee], callee
    return ""
