"""The end of a run: each group's outcome from its robots' reports, and the history after it."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from hfsm_behaviours.tararc.formulas import PAPER, Coefficients, belief
from hfsm_behaviours.tararc.grouping import pair
from hfsm_behaviours.tararc.history import History, Record, p_term, record_run
from hfsm_behaviours.tararc.plan import Plan


def group_outcomes(plan: Plan, reports: Mapping[str, bool]) -> list[bool]:
    """A group's task succeeded when robots are left in it and every one reported success."""
    return [bool(g["members"]) and all(reports.get(m, False) for m in g["members"]) for g in plan["groups"]]


def record_team(
    history: History,
    first: Plan,
    last: Plan,
    lost: Sequence[str],
    outcomes: Sequence[bool],
    coeff: Coefficients = PAPER,
) -> History:
    """The history after a run.

    The final groups gain a success or a failure from their outcomes (`record_run`); each robot
    lost gains a failed task, and so does its collaboration with every robot of its first group.
    Belief degrees are those of eq. 3 with the new records, at each robot's last place and task.
    """
    after = record_run(history, [g["members"] for g in last["groups"]], outcomes)
    pairs = dict(after.pairs)
    robots = dict(after.robots)
    gone = sorted(set(lost))
    failed_pairs: set[tuple[str, str]] = set()
    for robot in gone:
        robots[robot] = robots.get(robot, Record()).after(False)
        for g in first["groups"]:
            if robot in g["members"]:
                failed_pairs.update(pair(robot, m) for m in g["members"] if m != robot)
    for key in sorted(failed_pairs):
        pairs[key] = pairs.get(key, Record()).after(False)
    counted = History(pairs, robots)
    beliefs = {}
    for plan, who in ((last, None), (first, set(gone))):
        for g in plan["groups"]:
            for order, m in enumerate(g["members"]):
                if who is None or m in who:
                    energy = first["robots"][m]["energy"]
                    beliefs[m] = belief(p_term(counted, m), g["task"]["difficulty"], energy, order, coeff)
    merged = dict(history.beliefs)
    merged.update(beliefs)
    return History(pairs, robots, merged)



def merge_into(base: History, team: Sequence[str], updated: History) -> History:
    """`base` (the file as it is) with the team's records replaced by `updated`'s: robots and pairs
    outside the team are kept, so teams of different runs can share one file, and writing the same
    update twice gives the same file."""
    members = set(team)
    pairs = {k: r for k, r in base.pairs.items() if not (k[0] in members and k[1] in members)}
    pairs.update({k: r for k, r in updated.pairs.items() if k[0] in members and k[1] in members})
    robots = {k: r for k, r in base.robots.items() if k not in members}
    robots.update({k: r for k, r in updated.robots.items() if k in members})
    beliefs = {k: f for k, f in base.beliefs.items() if k not in members}
    beliefs.update({k: f for k, f in updated.beliefs.items() if k in members})
    return History(pairs, robots, beliefs)
