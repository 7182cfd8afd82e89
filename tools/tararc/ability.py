"""Figure 8, world-free: each group's ability in one allocation (eq. 4's B for the task it won, as
the auction computed it), the groups followed from allocation to allocation by their members, and
the group the bench fails in the third allocation.

The paper numbers its three groups and follows them over 4 allocations; TARARC regroups the team
before every allocation (from the history), so a group is followed here by its members: each
allocation's groups are matched one to one with the previous allocation's, the matching that keeps
the most robots in place (ties: the first matching in order).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm_behaviours.tararc.formulas import PAPER, Coefficients, belief, efficiency
from hfsm_behaviours.tararc.grouping import Robot, distance
from hfsm_behaviours.tararc.history import p_term
from hfsm_behaviours.tararc.plan import history_of

Plan = Mapping[str, Any]


def group_abilities(first: Plan, coeff: Coefficients = PAPER) -> list[dict[str, Any]]:
    """Each group of the plan the team made: its agent, members, the difficulty of the task it won,
    the agent's F (eq. 3) and B = F/C (eq. 4) for that task, exactly as the auction computed them:
    from the records the robots said, the agent's energy and start, and its place j_ord."""
    history = history_of({r: {"record": rec} for r, rec in first["records"].items()})
    out = []
    for g in first["groups"]:
        agent, task = g["agent"], g["task"]
        where = first["robots"][agent]
        order = g["members"].index(agent)
        f = belief(p_term(history, agent), task["difficulty"], where["energy"], order, coeff)
        gap = distance(Robot(agent, where["x"], where["y"]), Robot(task["id"], task["x"], task["y"]))
        out.append({"agent": agent, "members": list(g["members"]), "difficulty": task["difficulty"],
                    "F": round(f, 4), "B": round(efficiency(f, gap, task["difficulty"], coeff), 4)})
    return out


def failing_group(groups: Sequence[Mapping[str, Any]]) -> int:
    """The group the bench fails: the one that won the second hardest task (the paper's group 0, which
    had won harder tasks before it failed and then got the easiest), or the only one."""
    ranked = sorted(range(len(groups)), key=lambda i: (groups[i]["difficulty"], i))
    return ranked[-2] if len(ranked) > 1 else ranked[0]


def follow(allocations: Sequence[Sequence[Sequence[str]]]) -> list[list[int]]:
    """For each allocation (its groups' members), the lineage of each group: allocation 1's groups are
    lineages 0..n-1 in plan order; a later group takes the lineage of the previous allocation's group
    it is matched with (`match`)."""
    if not allocations:
        return []
    out = [list(range(len(allocations[0])))]
    for before, now in itertools.pairwise(allocations):
        pick = match(before, now)
        out.append([out[-1][j] for j in pick])
    return out


def match(before: Sequence[Sequence[str]], now: Sequence[Sequence[str]]) -> tuple[int, ...]:
    """For each group of `now`, the index of its group in `before`: the one-to-one matching that keeps
    the most robots together (the first such in order). Both must have the same number of groups."""
    if len(before) != len(now):
        raise ValueError(f"{len(before)} groups before, {len(now)} now")
    sets = [set(g) for g in before]

    def kept(pick: tuple[int, ...]) -> int:
        return sum(len(sets[j] & set(g)) for g, j in zip(now, pick, strict=True))

    return max(itertools.permutations(range(len(before))), key=lambda p: (kept(p), [-i for i in p]))


def paper_names(lineages: Sequence[Sequence[int]], difficulties: Sequence[Sequence[float]],
                failed: int | None) -> dict[int, int]:
    """A name for each lineage as the paper numbers its groups: the one failed in the third allocation
    is group 0; the others by the difficulty they won in allocation 1, the hardest last (the paper's
    group 2 always wins 0.9)."""
    first = dict(zip(lineages[0], difficulties[0], strict=True)) if lineages else {}
    rest = sorted((lin for lin in first if lin != failed), key=lambda lin: (first[lin], lin))
    order = ([failed] if failed is not None else []) + rest
    return {lin: name for name, lin in enumerate(order)}


def chain(runs: Sequence[Mapping[str, Any]]) -> list[dict[int, dict[str, Any]]]:
    """A chain of allocations as the paper plots it: for each allocation, each group by its paper
    name (`paper_names`) with its B, F, the difficulty it won and whether its task succeeded
    (`ok`: the group's outcome; False for a group all of whose robots failed)."""
    runs = [r for r in runs if r.get("groups")]
    lineages = follow([[g["members"] for g in r["groups"]] for r in runs])
    failed = None
    for run, lins in zip(runs, lineages, strict=True):
        down = set(run.get("failed", {}))
        hit = [lin for g, lin in zip(run["groups"], lins, strict=True) if down and set(g["members"]) <= down]
        if hit and failed is None:
            failed = hit[0]
    names = paper_names(lineages, [[g["difficulty"] for g in r["groups"]] for r in runs], failed)
    out = []
    for run, lins in zip(runs, lineages, strict=True):
        said = run.get("outcomes") or [run.get("completed", False)] * len(run["groups"])
        groups = zip(run["groups"], lins, said, strict=True)
        out.append({names[lin]: {**g, "ok": bool(ok)} for g, lin, ok in groups})
    return out
