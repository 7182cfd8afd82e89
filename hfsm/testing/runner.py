"""Run one checked case in process, world-free, and compare the run with what it expects."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from hfsm.autonomy import level_of
from hfsm.runtime.failing import Failure
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.testing.expect import Comparison, Mismatch
from hfsm.testing.plan import CasePlan
from hfsm.testing.standins import program_for
from hfsm.testing.world import ScriptedWorld
from hfsm.trace import ListTrace


@dataclass
class CaseResult:
    plan: CasePlan
    failures: list[Mismatch]
    result: RunResult
    trace: list[dict[str, Any]]

    @property
    def passed(self) -> bool:
        return not self.failures


def run_case(plan: CasePlan) -> CaseResult:
    if plan.verify is not None:
        from hfsm.testing.verify_case import verify_case  # the search: loaded only for such cases

        failures, _ = verify_case(plan)
        return CaseResult(plan, failures, RunResult({}, 0.0), [])
    program, calls = program_for(plan)
    inputs = [entry for entry, _ in plan.inputs]
    messages = [message for message, _ in plan.messages]
    world = ScriptedWorld(inputs, messages, plan.agents, plan.dt, plan.partners)
    trace = ListTrace()
    failing = [Failure(f.agent, f.at, f.reason) for f in plan.fail]
    options = RunOptions(
        plan.top,
        plan.agents,
        plan.params,
        plan.seed,
        plan.max_time,
        failing,
        plan.agent_params,
        scopes=plan.scopes,
        autonomy=level_of(plan.autonomy),
        decisions=plan.decisions,
    )
    try:
        result = run(program, world, options, trace)
    finally:
        world.close()
    failures = Comparison(plan, result, trace.records, calls).run()
    return CaseResult(plan, failures, result, trace.records)
