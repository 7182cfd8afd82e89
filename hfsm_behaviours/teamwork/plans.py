"""The plan from what the team said (steps 2-5), and after robots are lost (step 7)."""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.tararc.formulas import Coefficients
from hfsm_behaviours.tararc.plan import after_losses, make_plan, role_of


def coefficients_from(values: dict[str, Any]) -> Coefficients:
    """The paper's constants, with any of k1..k5, l1, l2 given in `values` instead."""
    known = Coefficients.__dataclass_fields__
    unknown = sorted(set(values) - set(known))
    if unknown:
        raise ValueError(f"unknown coefficients {unknown}; known: {sorted(known)}")
    return Coefficients(**{k: float(v) for k, v in values.items()})


@primitive(outcomes=["allocated"], outputs=["plan"])
def tararc_allocate(
    ctx: Context,
    *,
    mine: dict[str, Any],
    heard: dict[str, Any],
    tasks: list[Any],
    coefficients: dict[str, Any],
) -> Outcome:
    """Group, elect agents and let them compete for `tasks` from every robot's state (`mine`, this
    robot's; `heard`, the others' by id): every robot computes the same plan from the same states."""
    states = {**heard, ctx.agent: mine}
    return Outcome("allocated", plan=make_plan(states, tasks, coefficients_from(coefficients)))


@primitive(outcomes=["assigned", "excluded"], outputs=["plan", "role"])
def tararc_help(
    ctx: Context, *, plan: dict[str, Any], lost: list[Any], n_thres: int = 2, spacing: float = 1.0
) -> Outcome:
    """The plan after the robots `lost` (7a: a lost agent's member with the highest F takes over;
    7b: a group left with fewer than `n_thres` robots gets members of the nearest groups), and this
    robot's role in it; `excluded` when this robot is among the lost (a teammate took it for failed)."""
    gone = [str(r) for r in lost]
    now = after_losses(plan, gone, n_thres)
    role = role_of(now, ctx.agent, gone, spacing)
    if role is None:
        return Outcome("excluded", plan=now, role={})
    return Outcome("assigned", plan=now, role=role)
