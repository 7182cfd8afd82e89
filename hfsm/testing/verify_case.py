"""A behaviour test's `verify:` case: hfsm-verify's search over the case's machine and team; each
violation, or a search that could not finish, is a mismatch at the case's `verify` key."""

from __future__ import annotations

from hfsm.runtime.program import span_ticks
from hfsm.runtime.run import RunOptions
from hfsm.testing.expect import Mismatch
from hfsm.testing.plan import CasePlan
from hfsm.verify.build import bound_of, verify_program
from hfsm.verify.choices import Chooser
from hfsm.verify.properties import Properties
from hfsm.verify.search import Budget, Outcome, explore
from hfsm.verify.values import ANY, Scripts, Values


def verify_case(plan: CasePlan) -> tuple[list[Mismatch], Outcome]:
    asked = plan.verify
    assert asked is not None
    top = plan.loaded.machines[plan.top]
    chooser = Chooser()
    machines = sorted(n for n in plan.stand_ins if n in plan.loaded.machines)
    values = Values(scripts=_scripts(plan))
    program = verify_program(plan.loaded, plan.registry, machines, values, chooser, plan.dt)
    bound = bound_of(top, asked.bound, {a: plan.agent_params.get(a, plan.params) for a in plan.agents})
    options = RunOptions(
        plan.top,
        plan.agents,
        plan.params,
        plan.seed,
        bound,
        agent_params=plan.agent_params,
        scopes=plan.scopes,
    )
    budget = Budget(asked.loss, asked.delay, asked.fail, span_ticks(bound, plan.dt), asked.max_states)
    check = Properties(top.model.failure_outcomes, asked.goal == "success", None, bound)
    outcome = explore(program, options, budget, check, chooser, {})
    line, col = plan.doc.pos((*plan.path, "verify"), key=True)
    found = outcome.violation
    if found is not None:
        choices = "; ".join(f"t={c.tick * plan.dt:g} s: {c.what} {c.choice}" for c in found.choices[:10])
        message = f"verify: {found.kind} ({found.agent}): {found.text}" + (
            f" - after {choices}" if choices else ""
        )
        return [Mismatch(plan.file, line, col, message)], outcome
    if not outcome.exhausted:
        message = f"verify: not proved - the search stopped at {outcome.states} states (max_states)"
        return [Mismatch(plan.file, line, col, message)], outcome
    return [], outcome


def _scripts(plan: CasePlan) -> Scripts:
    """The outputs the case's stand-in scripts give, each step's a set a call may end with."""
    found: Scripts = {}
    for name, stand_in in plan.stand_ins.items():
        by_agent = found.setdefault(name, {})
        for agent, steps in stand_in.scripts.items():
            sets = by_agent.setdefault(ANY if agent is None else agent, [])
            for step in steps:
                if step.outputs not in sets:
                    sets.append(dict(step.outputs))
    return found
