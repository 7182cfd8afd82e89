"""The room's recovery decisions: who replaces whom, who is lent, when a pairing is spent, each a pure
step that machines/room_assign.yaml calls in turn (`job_of` composes the same steps).

What a robot does is a pure function of the plan and of what the team learns over the radio, each
a set that only grows: the robots lost, the tables done (at a wall), where survivors saw dropped
tables, the pairings spent and the slides (a survivor sliding its table to the wall alone, its
partner failed). Robots that heard the same, in any order, agree.

    job = {"role": "leader" | "assistant" | "spare" | "idle" | "stuck", "table": "table1" | "",
           "partner": "r2" | "", "channel": "table1_r1_r2_" | "", "at": [x, y], "toward": [x, y],
           "group": 0, "others": [...], "key": "k0", "slide": "" | "me" | "partner"}
          (+ "stuck": TABLE, "why": TEXT when stuck)

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

from hfsm_behaviours.room.cramped import slide_job
from hfsm_behaviours.tararc.plan import Plan, after_losses

PAIR = 2
ROLES = ("leader", "assistant", "spare", "idle")
TRIES = 4  # pairings of one table that may end without it at its wall before the team gives it up


def _where(plan: Plan, robot: str) -> tuple[float, float]:
    r = plan["robots"][robot]
    return float(r["x"]), float(r["y"])


def replaced(plan: Plan, lost: Sequence[str]) -> list[dict[str, Any]]:
    """Who replaces whom (TARARC's 7a and 7b, `after_losses`): a group gives only robots beyond its
    pair, its agent and assistant carry on; a lost agent's place goes to its assistant, a lost
    assistant's to a spare."""
    return [dict(g) for g in after_losses(plan, lost, PAIR, keep=PAIR)["groups"]]


def lent(plan: Plan, groups: Sequence[Mapping[str, Any]], done: Sequence[str]) -> list[dict[str, Any]]:
    """Who is lent: a group left short of a pair with its table not done borrows the robots of the
    groups whose tables are done, nearest its agent (or table) first, ties by id; two lone robots
    of short tables pair up; the first borrowed of a group with no robot left becomes its agent."""
    out = [dict(g) for g in groups]
    finished = set(done)
    for needy in out:
        if needy["task"]["id"] in finished:
            continue
        while len(needy["members"]) < PAIR:
            free = [(g, m) for g in out if g["task"]["id"] in finished for m in g["members"]]
            if not free and len(needy["members"]) == PAIR - 1:  # two lone robots of short tables pair up
                free = [(g, m) for g in out if g is not needy and g["task"]["id"] not in finished
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
    return out


def groups_after(plan: Plan, lost: Sequence[str], done: Sequence[str]) -> list[dict[str, Any]]:
    """Step 7 for the room: `replaced`, then `lent`."""
    return lent(plan, replaced(plan, lost), done)


def key_of(lost: Sequence[str], done: Sequence[str]) -> str:
    """A name for the plan after these losses and finished tables: `k0` with neither."""
    if not lost and not done:
        return "k0"
    text = ",".join(sorted(set(lost))) + "|" + ",".join(sorted(set(done)))
    return "k" + hashlib.sha1(text.encode()).hexdigest()[:8]


def channel_of(table: str, leader: str, assistant: str, spent: Sequence[str]) -> str:
    """When a pairing is spent: the prefix of every message and barrier name of a pairing is the
    table and the pair, and after k pairings of the same pair on the same table that both robots
    gave up (`spent` holds "CHANNEL/ROBOT" for each robot whose carry on CHANNEL ended without the
    table at a wall), the number k: the pair tries again on a new channel only once both know the
    last try is over."""
    base = f"{table}_{leader}_{assistant}_"
    pair = {leader, assistant}
    spent_by = spent_channels(spent)
    tries = sum(1 for channel, robots in spent_by.items() if channel.startswith(base) and pair <= robots)
    return f"{base}{tries}_" if tries else base


def spent_channels(spent: Sequence[str]) -> dict[str, set[str]]:
    """Each channel named in `spent` ("CHANNEL/ROBOT"), with the robots that said it spent."""
    by: dict[str, set[str]] = {}
    for entry in set(spent):
        channel, _, robot = entry.rpartition("/")
        by.setdefault(channel, set()).add(robot)
    return by


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


def tried(done: Sequence[str], spent: Sequence[str], tables: Sequence[str],
          tries: int = TRIES) -> dict[str, int]:
    """The tables given up: not done, and `tries` pairings of them or more ended without them at their
    wall (the channels named in `spent`, "CHANNEL/ROBOT", a channel being "TABLE_LEADER_ASSISTANT_"
    and its tries), each with that count. Its robots are then free for the other tables, and once
    only given-up tables are left the team ends `stuck` saying so (`stranded`), not at its time
    limit (held-out room walls-40000: one pair searched for a table pushed off its place, try
    after try, until the limit)."""
    finished = set(done)
    channels: dict[str, set[str]] = {}
    for channel in spent_channels(spent):
        for table in tables:
            if table not in finished and channel.startswith(f"{table}_"):
                channels.setdefault(table, set()).add(channel)
    return {t: len(c) for t, c in sorted(channels.items()) if len(c) >= tries}


def stranded(groups: Sequence[Mapping[str, Any]], done: Sequence[str], sliding: bool,
             gone: Mapping[str, int] | None = None) -> dict[str, str]:
    """When no pair is left for any table not yet done (fewer than two robots alive, no slide going
    on), or every table not done was given up (`gone`, with its tries: `tried`): the first such
    table and why, which ends the room honestly; else {}."""
    given_up = dict(gone or {})
    finished = set(done) | set(given_up)
    left = [g for g in groups if g["task"]["id"] not in finished]
    if not left and given_up:
        table = min(given_up, key=lambda t: (len(t), t))
        n = given_up[table]
        return {"stuck": table, "why": f"{table}: {n} tries by its pairs ended without it at its wall"}
    if not left or sliding or any(len(g["members"]) >= PAIR for g in left):
        return {}
    alive = sorted({m for g in groups for m in g["members"]}, key=lambda r: (len(r), r))
    table = str(left[0]["task"]["id"])
    who = f"{len(alive)} robot{'' if len(alive) == 1 else 's'} left alive ({', '.join(alive) or 'none'})"
    return {"stuck": table, "why": f"{table} needs two robots to lift it and {who}"}


def place_of(me: str, groups: Sequence[Mapping[str, Any]], done: Sequence[str]) -> dict[str, Any]:
    """This robot's place in the groups: `role` (one of ROLES: leader and assistant are the group's
    agent and its first other member, the others spares; idle when its table is done or it is in
    no group), `group` (-1: none), `table`, and `leader` and `assistant` of its group ('' if none)."""
    for index, g in enumerate(groups):
        if me not in g["members"]:
            continue
        others = [m for m in g["members"] if m != g["agent"]]
        pair = {"leader": str(g["agent"] or "") if others else "", "assistant": others[0] if others else ""}
        role = ("idle" if g["task"]["id"] in set(done) else "leader" if me == pair["leader"]
                else "assistant" if me == pair["assistant"] else "spare")
        return {"role": role, "group": index, "table": str(g["task"]["id"]), **pair}
    return {"role": "idle", "group": -1, "table": "", "leader": "", "assistant": ""}


def job_in(plan: Plan, me: str, place: Mapping[str, Any], channel: str, lost: Sequence[str],
           done: Sequence[str], seen: Mapping[str, Sequence[float]], stuck: Mapping[str, str],
           spent: Sequence[str] = ()) -> dict[str, Any]:
    """The job as the machines carry it, from this robot's place and its pairing's channel; `slide`:
    who of the pair slides a table with no room at one side alone (`cramped.slide_job`)."""
    alive = sorted(r for r in plan["robots"] if r not in set(lost))
    job: dict[str, Any] = {"role": place["role"], "table": place["table"], "partner": "", "channel": "",
                           "at": [], "toward": [], "group": place["group"],
                           "others": [r for r in alive if r != me], "key": key_of(lost, done)}
    if place["table"] and place["role"] != "idle":
        table = plan["tables"][place["table"]]
        at = seen.get(table["id"], [table["x"], table["y"]])
        job.update(at=[float(at[0]), float(at[1])], toward=list(table["toward"]))
    if place["role"] in ("leader", "assistant"):
        partner = place["assistant"] if place["role"] == "leader" else place["leader"]
        job.update(partner=partner, channel=channel,
                   slide=slide_job(plan["tables"], place, me, plan["robots"], channel, spent))
    return {**job, "role": "stuck", **stuck} if stuck else job


def job_of(plan: Plan, me: str, lost: Sequence[str], done: Sequence[str],
           seen: Mapping[str, Sequence[float]], spent: Sequence[str] = (),
           sliding: Sequence[str] = ()) -> dict[str, Any] | None:
    """What robot `me` does; None when it is among the lost: the steps of machines/room_assign.yaml."""
    if me in set(lost):
        return None
    slid = sliding_partners(lost, done, spent, sliding)
    gone = tried(done, spent, sorted(plan["tables"]))
    over = [*done, *gone]
    groups = lent(plan, replaced(plan, sorted(set(lost) - slid)), over)
    place = place_of(me, groups, over)
    pair = place["table"], place["leader"], place["assistant"]
    channel = channel_of(*pair, spent) if place["leader"] else ""
    return job_in(plan, me, place, channel, lost, done, seen, stranded(groups, done, bool(slid), gone), spent)
