"""Run the cases of tests/machines/tararc*.test.yaml again, on a lossy radio or with other params."""

from __future__ import annotations

import random
from dataclasses import replace
from pathlib import Path
from typing import Any

from hfsm.primitive import Message
from hfsm.runtime.failing import Failure
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.testing.check import read_test_file
from hfsm.testing.plan import CasePlan
from hfsm.testing.standins import program_for
from hfsm.testing.world import ScriptedWorld
from hfsm.trace import TraceSink

MACHINES = Path(__file__).resolve().parent / "machines"


class LossyWorld(ScriptedWorld):
    """The behaviour tests' world with a radio that loses each message and barrier notice with
    probability `loss`, drawn from a seeded generator (the same seed, the same losses)."""

    def __init__(self, plan: CasePlan, loss: float, seed: int) -> None:
        super().__init__([e for e, _ in plan.inputs], [m for m, _ in plan.messages], plan.agents, plan.dt)
        self.loss = loss
        self.rng = random.Random(seed)
        self.lost = 0

    def post(self, message: Message) -> None:
        if self.rng.random() < self.loss:
            self.lost += 1
            return
        super().post(message)


def case(file: str, name: str) -> CasePlan:
    for plan in read_test_file(MACHINES / file):
        if plan.name == name:
            return plan
    raise KeyError(name)


def run_plan(plan: CasePlan, loss: float = 0.0, seed: int = 0, trace: TraceSink | None = None,
             **params: Any) -> tuple[RunResult, int]:
    """The case's run (stand-ins, inputs, messages, failures as in its file); (result, messages lost).
    `trace`: a sink for the run's trace records."""
    plan = replace(plan, params={**plan.params, **params})
    program, _ = program_for(plan)
    world = LossyWorld(plan, loss, seed)
    failing = [Failure(f.agent, f.at, f.reason) for f in plan.fail]
    options = RunOptions(plan.top, plan.agents, plan.params, plan.seed, plan.max_time, failing)
    try:
        result = run(program, world, options, trace)
    finally:
        world.close()
    assert result.error is None, result.error
    return result, world.lost


def decisions(result: RunResult, keys: tuple[str, ...]) -> dict[str, Any]:
    """Each agent's outcome and the outputs named: what the team decided, not when."""
    return {
        name: (agent.outcome, {k: agent.outputs.get(k) for k in keys})
        for name, agent in sorted(result.agents.items())
    }
