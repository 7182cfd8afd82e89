"""The room's plan: TARARC's groups, one per table, each a pair (the agent leads, its first other member
assists) and its spares; and what each robot does after losses and finished tables.

A plan is `hfsm_behaviours.tararc.plan`'s (groups with their tasks, start positions, beliefs) plus the
tables and their claimed walls. What a robot does is a pure function of the plan and of what
the team learns over the radio, each a set that only grows: the robots lost, the tables done
(at a wall), where survivors saw dropped tables, the pairings spent and the slides (a survivor
sliding its table to the wall alone, its partner failed). Robots that heard the same, in any order,
agree.

    job = {"role": "leader" | "assistant" | "spare" | "idle" | "stuck", "table": "table1" | "",
           "partner": "r2" | "", "channel": "table1_r1_r2_" | "", "at": [x, y], "toward": [x, y],
           "group": 0, "others": [...], "key": "k0"}  (+ "stuck": TABLE, "why": TEXT when stuck)

`at` (where the table is believed to be) and `toward` are in the room's frame. A robot whose carry
ended without its table at a wall says the pairing is spent (news too); once both robots of a pair
said so, the same pair tries again on a new channel (`channel_of`). A spare waits in its
group until help makes it an assistant; `idle` robots' tables are done (or they are in no group with
work): they may be lent to a group left short (below). While a survivor slides its table alone
(`slide_of`), its failed partner still counts as in its group, so no helper is lent to that table;
a slide ends with the table done or the survivor's pairing spent (or the survivor lost), and then
help comes as for any loss.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm_behaviours.room.claims import Rect, claim_walls, turns
from hfsm_behaviours.room.frames import difficulty_of
from hfsm_behaviours.room.stations import room_ties
from hfsm_behaviours.tararc.formulas import PAPER, Coefficients
from hfsm_behaviours.tararc.plan import Plan, after_losses, make_plan

PAIR = 2


def tables_of(tasks: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """The tables among the team's tasks (in.tasks), each with its difficulty from its size."""
    out = []
    for i, t in enumerate(tasks):
        if t.get("kind", "table") != "table":
            continue
        length, width = float(t.get("length", 0.8)), float(t.get("width", 0.5))
        out.append({"id": str(t["id"]), "x": float(t["x"]), "y": float(t["y"]),
                    "yaw": float(t.get("yaw", 0.0)),
                    "length": length, "width": width, "difficulty": difficulty_of(length, width),
                    "priority": int(t.get("priority", i + 1))})
    return out


def make_room_plan(states: Mapping[str, Mapping[str, Any]], tasks: Sequence[Mapping[str, Any]],
                   room: Mapping[str, Any], coeff: Coefficients = PAPER, reach: float = 0.5) -> Plan:
    """TARARC's steps 2-5 with one group per table (relevance ties by the robots' stations,
    `stations.room_ties`), every table's claimed wall and the tables it waits for (`claims.turns`:
    `after`), and every robot's colour as it said it (-1:
    not said), for a robot to look for its partner."""
    tables = tables_of(tasks)
    if len(states) < PAIR * len(tables):
        raise ValueError(f"{len(states)} robots cannot make {len(tables)} pairs")
    plan = make_plan(states, tables, coeff, room_ties(states, tables))
    ways = claim_walls(tables, float(room["width"]), float(room["depth"]), reach)
    after = turns(ways, tables, reach)
    plan["tables"] = {t["id"]: {**t, "toward": list(ways[t["id"]].toward), "after": after[t["id"]],
                                "corridor": _rect(ways[t["id"]].corridor)} for t in tables}
    plan["colours"] = {r: int(s.get("colour", -1)) for r, s in sorted(states.items())}
    return plan


def _rect(r: Rect) -> list[float]:
    """A corridor as [x, y, yaw (radians), length, width], rounded to the millimetre."""
    return [round(r.cx, 3), round(r.cy, 3), round(math.atan2(r.uy, r.ux), 4), round(2 * r.half_length, 3),
            round(2 * r.half_width, 3)]


def drawn(plan: Plan, job: Mapping[str, Any], done: Sequence[str], where: Mapping[str, Sequence[float]]
          ) -> dict[str, list[list[Any]]]:
    """What the monitor's room view draws of one robot's belief (room frame): the claimed corridors
    of the tables not done, where the robot believes its table stands, and where it believes each
    teammate last stood."""
    rects = [[*t["corridor"], f"{t['id']} corridor"] for t in plan["tables"].values()
             if "corridor" in t and t["id"] not in set(done)]
    points = [[round(float(p[0]), 3), round(float(p[1]), 3), str(r)] for r, p in sorted(where.items())]
    if job.get("at"):
        points.append([round(float(job["at"][0]), 3), round(float(job["at"][1]), 3), f"{job['table']}?"])
    return {"rects": rects, "points": points}


def _where(plan: Plan, robot: str) -> tuple[float, float]:
    r = plan["robots"][robot]
    return float(r["x"]), float(r["y"])


def groups_after(plan: Plan, lost: Sequence[str], done: Sequence[str]) -> list[dict[str, Any]]:
    """Step 7 (TARARC's 7a and 7b, `after_losses`: a group gives only robots beyond its pair, its
    agent and assistant carry on), then a group left short of a pair with its table
    not done borrows the robots of the groups whose tables are done, nearest its agent (or table)
    first, ties by id; the first borrowed of a group with no robot left becomes its agent."""
    groups = [dict(g) for g in after_losses(plan, lost, PAIR, keep=PAIR)["groups"]]
    finished = set(done)
    for needy in groups:
        if needy["task"]["id"] in finished:
            continue
        while len(needy["members"]) < PAIR:
            free = [(g, m) for g in groups if g["task"]["id"] in finished for m in g["members"]]
            if not free and len(needy["members"]) == PAIR - 1:  # two lone robots of short tables pair up
                free = [(g, m) for g in groups if g is not needy and g["task"]["id"] not in finished
                        and len(g["members"]) < PAIR for m in g["members"]]
            if not free:
                break
            task = needy["task"]
            here = _where(plan, needy["agent"]) if needy["agent"] else (task["x"], task["y"])
            giver, robot = min(free, key=lambda gm: (math.dist(_where(plan, gm[1]), here), gm[1]))
            giver["members"] = [m for m in giver["members"] if m != robot]
            if giver["agent"] == robot:
                giver["agent"] = giver["members"][0] if giver["members"] else None
            needy["members"] = [*needy["members"], robot]
            needy["agent"] = needy["agent"] or robot
    return groups


def key_of(lost: Sequence[str], done: Sequence[str]) -> str:
    """A name for the plan after these losses and finished tables: `k0` with neither."""
    if not lost and not done:
        return "k0"
    text = ",".join(sorted(set(lost))) + "|" + ",".join(sorted(set(done)))
    return "k" + hashlib.sha1(text.encode()).hexdigest()[:8]


def channel_of(table: str, leader: str, assistant: str, spent: Sequence[str]) -> str:
    """The prefix of every message and barrier name of a pairing: the table and the pair, and after
    k pairings of the same pair on the same table that both robots gave up (`spent` holds
    "CHANNEL/ROBOT" for each robot whose carry on CHANNEL ended without the table at a wall), the
    number k: the pair tries again on a new channel only once both know the last try is over."""
    base = f"{table}_{leader}_{assistant}_"
    by: dict[str, set[str]] = {}
    for entry in set(spent):
        channel, _, robot = entry.rpartition("/")
        if channel.startswith(base):
            by.setdefault(channel, set()).add(robot)
    tries = sum(1 for robots in by.values() if {leader, assistant} <= robots)
    return f"{base}{tries}_" if tries else base


def slide_of(table: str, channel: str, robot: str, partner: str) -> str:
    """The news that `robot`, left alone on `channel` by `partner`, slides `table` to its wall."""
    return f"{table}/{channel}/{robot}/{partner}"


def sliding_partners(lost: Sequence[str], done: Sequence[str], spent: Sequence[str],
                     sliding: Sequence[str]) -> set[str]:
    """The failed partners of the slides still going on: the survivor is not lost, its table is not
    done and it has not said its pairing spent (a slide that ended without the table at its wall)."""
    gone, finished, over = set(lost), set(done), set(spent)
    kept = set()
    for entry in set(sliding):
        parts = entry.split("/")
        if len(parts) != 4:
            continue
        table, channel, robot, partner = parts
        if robot not in gone and table not in finished and f"{channel}/{robot}" not in over:
            kept.add(partner)
    return kept


def stranded(plan: Plan, groups: Sequence[Mapping[str, Any]], done: Sequence[str], sliding: bool
             ) -> dict[str, str]:
    """When no pair is left for any table not yet done (fewer than two robots alive, no slide going
    on): the first such table and why, which ends the room honestly; else {}."""
    finished = set(done)
    left = [g for g in groups if g["task"]["id"] not in finished]
    if not left or sliding or any(len(g["members"]) >= PAIR for g in left):
        return {}
    alive = sorted({m for g in groups for m in g["members"]}, key=lambda r: (len(r), r))
    table = str(left[0]["task"]["id"])
    who = f"{len(alive)} robot{'' if len(alive) == 1 else 's'} left alive ({', '.join(alive) or 'none'})"
    return {"stuck": table, "why": f"{table} needs two robots to lift it and {who}"}


def job_of(plan: Plan, me: str, lost: Sequence[str], done: Sequence[str],
           seen: Mapping[str, Sequence[float]], spent: Sequence[str] = (),
           sliding: Sequence[str] = ()) -> dict[str, Any] | None:
    """What robot `me` does; None when it is among the lost."""
    if me in set(lost):
        return None
    alive = sorted(r for r in plan["robots"] if r not in set(lost))
    job: dict[str, Any] = {"role": "idle", "table": "", "partner": "", "channel": "", "at": [], "toward": [],
                           "group": -1, "others": [r for r in alive if r != me], "key": key_of(lost, done)}
    slid = sliding_partners(lost, done, spent, sliding)
    grouped = sorted(set(lost) - slid)
    groups = groups_after(plan, grouped, done)
    left = stranded(plan, groups, done, bool(slid))
    mine = _job_in(plan, me, groups, done, seen, spent, job)
    return {**mine, "role": "stuck", **left} if left else mine


def unmanned(plan: Plan, lost: Sequence[str], done: Sequence[str], spent: Sequence[str] = (),
             sliding: Sequence[str] = ()) -> list[str]:
    """The tables not yet done that no pair is left for (their group short, no slide on them): no
    other table's turn waits for one (it would wait until the room's limit); robots freed when the
    others are done come for it."""
    slid = sliding_partners(lost, done, spent, sliding)
    finished = set(done)
    return sorted(str(g["task"]["id"]) for g in groups_after(plan, sorted(set(lost) - slid), done)
                  if g["task"]["id"] not in finished and len(g["members"]) < PAIR)


def _job_in(plan: Plan, me: str, groups: list[dict[str, Any]], done: Sequence[str],
            seen: Mapping[str, Sequence[float]], spent: Sequence[str], job: dict[str, Any]) -> dict[str, Any]:
    for index, g in enumerate(groups):
        if me not in g["members"]:
            continue
        table = plan["tables"][g["task"]["id"]]
        job.update(group=index, table=table["id"])
        if table["id"] in set(done):
            return {**job, "role": "idle"}
        at = seen.get(table["id"], [table["x"], table["y"]])
        job.update(at=[float(at[0]), float(at[1])], toward=list(table["toward"]))
        others = [m for m in g["members"] if m != g["agent"]]
        if len(others) == 0:
            return {**job, "role": "spare"}  # alone: waits for help
        leader, assistant = g["agent"], others[0]
        channel = channel_of(table["id"], leader, assistant, spent)
        if me == leader:
            return {**job, "role": "leader", "partner": assistant, "channel": channel}
        if me == assistant:
            return {**job, "role": "assistant", "partner": leader, "channel": channel}
        return {**job, "role": "spare"}
    return job
