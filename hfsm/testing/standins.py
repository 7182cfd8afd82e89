"""Stand-ins as primitives: each call plays the next step of its script (the last step repeats)."""

from __future__ import annotations

import dataclasses
import math
from collections import Counter
from typing import Any

from hfsm.primitive import Context, Outcome, Primitive
from hfsm.registry import Registry
from hfsm.runtime.program import Program
from hfsm.testing.plan import CasePlan, StandInPlan


class Calls:
    """How many times each agent called each stand-in, and with which params."""

    def __init__(self) -> None:
        self.count: Counter[tuple[str, str]] = Counter()
        self.params: dict[tuple[str, str], list[dict[str, Any]]] = {}


def _stand_in(name: str, plan: StandInPlan, calls: Calls) -> Primitive:
    def play(ctx: Context, **params: Any) -> str | Outcome:
        key = (ctx.agent, name)
        n = calls.count[key]
        calls.count[key] += 1
        calls.params.setdefault(key, []).append({**params, "scope": ctx.scope} if ctx.scope else params)
        steps = plan.steps_for(ctx.agent)
        if steps is None:
            raise LookupError(f"the stand-in for '{name}' has no script for agent '{ctx.agent}' (by_agent)")
        step = steps[min(n, len(steps) - 1)]
        ctx.wait(step.after)
        if step.outcome is None:
            ctx.wait(math.inf)
        return Outcome(str(step.outcome), **step.outputs)

    spec = dataclasses.replace(plan.spec, kind="primitive", world=None)
    return Primitive(spec, play)


def program_for(plan: CasePlan) -> tuple[Program, Calls]:
    """The case's program: machines only stand-ins call left out, stand-ins in the place of behaviours,
    and no primitive of any world."""
    calls = Calls()
    registry = Registry(
        p for p in plan.registry if p.spec.world is None and p.spec.name not in plan.stand_ins
    )
    registry.add(*(_stand_in(name, s, calls) for name, s in plan.stand_ins.items()))
    machines = {
        n: m for n, m in plan.loaded.machines.items() if n not in plan.stand_ins and n not in plan.pruned
    }
    return Program(machines, registry, plan.dt), calls
