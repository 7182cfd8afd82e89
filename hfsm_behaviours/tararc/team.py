"""Steps 2-5 from what every robot knows after one round of broadcasts: positions, energies, the
shared history and the task list. This is what a `tararc_groups`/`assign` primitive will call."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from hfsm_behaviours.tararc.allocation import Task, compete
from hfsm_behaviours.tararc.formulas import PAPER, Coefficients, belief, election_difficulty
from hfsm_behaviours.tararc.grouping import Group, Robot, Ties, form_groups, group_of
from hfsm_behaviours.tararc.history import History, p_term, relevance_matrix


@dataclass(frozen=True)
class Allocation:
    groups: tuple[Group, ...]
    tasks: tuple[tuple[str, int], ...]
    """(task id, group index) in priority order."""
    beliefs: Mapping[str, float]
    """F of every robot at its place in its group, for the election's d_t (mean task difficulty)."""


def allocate(
    robots: Sequence[Robot],
    tasks: Sequence[Task],
    history: History,
    energy: Mapping[str, float],
    coeff: Coefficients = PAPER,
    ties: Ties | None = None,
) -> Allocation:
    """One group per task (N_g = number of tasks), agents elected, tasks auctioned among agents;
    relevance ties in the grouping broken by `ties` (then id)."""
    if not tasks:
        raise ValueError("no tasks to allocate")
    ids = [r.id for r in robots]
    d_mean = election_difficulty([t.difficulty for t in tasks])

    def f(robot: str, order: int, difficulty: float) -> float:
        return belief(p_term(history, robot), difficulty, energy[robot], order, coeff)

    rel = relevance_matrix(history, ids)
    groups = form_groups(robots, len(tasks), rel, lambda r, o: f(r, o, d_mean), ties)
    by_id = {r.id: r for r in robots}
    agents = [by_id[g.agent] for g in groups]

    def belief_at(agent: str, difficulty: float) -> float:
        return f(agent, groups[group_of(groups, agent)].order(agent), difficulty)

    won = compete(tasks, agents, belief_at, coeff)
    beliefs = {m: f(m, g.order(m), d_mean) for g in groups for m in g.members}
    return Allocation(
        groups=tuple(groups),
        tasks=tuple((task, group_of(groups, agent)) for task, agent in won),
        beliefs=dict(sorted(beliefs.items())),
    )
