"""The team's plan as plain data (what machines carry in vars and robots agree on over the radio).

A plan is made once from the broadcast states (`make_plan`, steps 2-5) and then recomputed from
it and the set of robots lost (`after_losses`, step 7) whenever that set grows: a pure function of
the set, so robots that heard of the same losses, in whatever order, hold the same plan.

    {"robots":  {"r0": {"x": 0.0, "y": 1.0, "energy": 0.9}, ...},
     "groups":  [{"agent": "r0", "members": ["r0", "r3"], "task": {"id": "t0", "x": .., "y": ..,
                  "difficulty": 0.5}}, ...],
     "beliefs": {"r0": 0.52, ...},
     "records": {"r0": {"n_s": 1, "n_f": 0, "pairs": {"r3": [1, 0]}}, ...}}

`records` are the robots' history as they said it, so the end of the run can update the file.

A group all of whose robots were lost keeps its task with `agent: null, members: []`.
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm_behaviours.tararc.allocation import Task
from hfsm_behaviours.tararc.formation import enclose, form_places
from hfsm_behaviours.tararc.formulas import PAPER, Coefficients
from hfsm_behaviours.tararc.grouping import Group, Robot, Ties
from hfsm_behaviours.tararc.help import apply_transfers, hand_over, lend
from hfsm_behaviours.tararc.history import History, Record
from hfsm_behaviours.tararc.team import allocate

Plan = dict[str, Any]


def history_of(states: Mapping[str, Mapping[str, Any]]) -> History:
    """The history the team agrees on, from every robot's broadcast record.

    Each robot says its own task record and its pairs; the record of pair (a, b) is taken from
    the smaller id's broadcast, so one copy is read whatever the others said.
    """
    robots: dict[str, Record] = {}
    beliefs: dict[str, float] = {}
    pairs: dict[tuple[str, str], Record] = {}
    for robot, state in sorted(states.items()):
        record = state.get("record", {})
        robots[robot] = Record(int(record.get("n_s", 0)), int(record.get("n_f", 0)))
        if "belief" in record:
            beliefs[robot] = float(record["belief"])
        for other, counts in sorted(record.get("pairs", {}).items()):
            if other in states and robot < other:
                pairs[(robot, other)] = Record(int(counts[0]), int(counts[1]))
    return History(pairs, robots, beliefs)


def record_of(history: History, robot: str) -> dict[str, Any]:
    """What a robot says of its history: its task record, its last F, its pairs (`history_of`)."""
    rec = history.robot_record(robot)
    out: dict[str, Any] = {"n_s": rec.n_s, "n_f": rec.n_f}
    if robot in history.beliefs:
        out["belief"] = history.beliefs[robot]
    mine = ((a, b, r) for (a, b), r in history.pairs.items() if robot in (a, b))
    out["pairs"] = {b if a == robot else a: [r.n_s, r.n_f] for a, b, r in mine}
    return out


def task_of(entry: Mapping[str, Any], priority: int) -> Task:
    return Task(str(entry["id"]), float(entry["x"]), float(entry["y"]), float(entry["difficulty"]),
                int(entry.get("priority", priority)))


def make_plan(
    states: Mapping[str, Mapping[str, Any]], tasks: Sequence[Mapping[str, Any]], coeff: Coefficients = PAPER,
    ties: Ties | None = None,
) -> Plan:
    """Steps 2-5 from the states every robot heard: groups (relevance ties by `ties`, then id),
    agents, tasks won by the agents."""
    robots = [Robot(r, float(s["x"]), float(s["y"])) for r, s in sorted(states.items())]
    task_list = [task_of(t, i) for i, t in enumerate(tasks)]
    energy = {r: float(s["energy"]) for r, s in states.items()}
    done = allocate(robots, task_list, history_of(states), energy, coeff, ties)
    by_id = {t.id: t for t in task_list}
    won = {g: by_id[t] for t, g in done.tasks}
    groups = []
    for i, g in enumerate(done.groups):
        task = won[i]  # one group per task, so every agent wins one
        entry = {"id": task.id, "x": task.x, "y": task.y, "difficulty": task.difficulty}
        groups.append({"agent": g.agent, "members": list(g.members), "task": entry})
    return {
        "robots": {r.id: {"x": r.x, "y": r.y, "energy": energy[r.id]} for r in robots},
        "groups": groups,
        "beliefs": dict(done.beliefs),
        "records": {r.id: dict(states[r.id].get("record", {})) for r in robots},
    }


def after_losses(plan: Plan, lost: Sequence[str], n_thres: int, keep: int = 1) -> Plan:
    """Step 7 for every robot lost, in id order: 7a when it was an agent (the member with the
    highest F takes over), then 7b for every group left with fewer than n_thres robots (a giver
    keeps its first `keep` members, `help.lend`)."""
    groups: list[Group | None] = [Group(g["agent"], tuple(g["members"])) if g["members"] else None
                                  for g in plan["groups"]]
    for robot in sorted(set(lost)):
        for i, group in enumerate(groups):
            if group is None or robot not in group.members:
                continue
            if robot == group.agent:
                handed = hand_over(group, 0.0, 1.0, plan["beliefs"])  # lost: no energy left
                groups[i] = None if handed is None else handed.group
            else:
                groups[i] = Group(group.agent, tuple(m for m in group.members if m != robot))
    where = {r: Robot(r, s["x"], s["y"]) for r, s in plan["robots"].items()}
    for needy in range(len(groups)):
        live = [i for i, g in enumerate(groups) if g is not None]
        if needy not in live:
            continue
        kept = [g for g in groups if g is not None]
        moved = lend(kept, live.index(needy), n_thres, where, keep)
        for i, g in zip(live, apply_transfers(kept, moved), strict=True):
            groups[i] = g
    out = []
    for entry, group in zip(plan["groups"], groups, strict=True):
        agent, members = (None, []) if group is None else (group.agent, list(group.members))
        out.append({"agent": agent, "members": members, "task": entry["task"]})
    return {**plan, "groups": out}


def key_of(lost: Sequence[str]) -> str:
    """A name for the plan after these losses (for barrier names): `k0` with none lost."""
    if not lost:
        return "k0"
    return "k" + hashlib.sha1(",".join(sorted(set(lost))).encode()).hexdigest()[:8]


GAP = 0.8  # robots stand at least GAP * spacing apart when formed up and round a task


def bounds_of(plan: Plan) -> tuple[tuple[float, float], tuple[float, float]]:
    """The box the team's starts and its tasks span: places outside it may be outside the room."""
    xs = [s["x"] for s in plan["robots"].values()] + [g["task"]["x"] for g in plan["groups"]]
    ys = [s["y"] for s in plan["robots"].values()] + [g["task"]["y"] for g in plan["groups"]]
    return ((min(xs), min(ys)), (max(xs), max(ys)))


def places_of(plan: Plan, spacing: float) -> dict[str, tuple[float, float]]:
    """Every robot's place when its group has formed up (`formation.form_places`)."""
    starts = {r: (s["x"], s["y"]) for r, s in plan["robots"].items()}
    groups = [(g["agent"], g["members"]) for g in plan["groups"] if g["members"]]
    return form_places(groups, starts, bounds_of(plan), spacing, GAP * spacing)


def role_of(plan: Plan, me: str, lost: Sequence[str], spacing: float) -> dict[str, Any] | None:
    """What robot `me` does under the plan; None when it is in no group (lost).

    The agent's place is the task itself and, for forming up, its own start; members form up near
    their agent and enclose the task on a ring round it (step 6, `formation`). Places are worked
    out from the first plan's groups: a plan changed by help skips forming up.
    """
    for index, g in enumerate(plan["groups"]):
        if me not in g["members"]:
            continue
        task = g["task"]
        members = [m for m in g["members"] if m != g["agent"]]
        formed = places_of(plan, spacing)
        agent = formed.get(g["agent"], (plan["robots"][g["agent"]]["x"], plan["robots"][g["agent"]]["y"]))
        if me == g["agent"]:
            slot = (task["x"], task["y"])
        else:
            where = {m: formed.get(m, (plan["robots"][m]["x"], plan["robots"][m]["y"])) for m in members}
            slot = enclose((task["x"], task["y"]), members, where, spacing, GAP * spacing, agent,
                           bounds_of(plan))[me]
        form = formed.get(me, (plan["robots"][me]["x"], plan["robots"][me]["y"]))
        alive = sorted(r for r in plan["robots"] if r not in set(lost))
        return {
            "group": index,
            "role": "agent" if me == g["agent"] else "member",
            "agent": g["agent"],
            "task": task["id"],
            "mates": [m for m in g["members"] if m != me],
            "others": [r for r in alive if r != me],
            "slot": {"x": round(slot[0], 6), "y": round(slot[1], 6)},
            "form": {"x": round(form[0], 6), "y": round(form[1], 6)},
            "first": not lost,
            "key": key_of(lost),
        }
    return None
