"""The room's plan: TARARC's groups, one per table, each a pair (the agent leads, its first other member
assists) and its spares; the tables and their claimed walls. What each robot does after losses and
finished tables is `hfsm_behaviours.room.recovery`'s, step by step in machines/room_assign.yaml."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm_behaviours.room.claims import Rect, claim_walls, turns
from hfsm_behaviours.room.cramped import free_place
from hfsm_behaviours.room.frames import difficulty_of
from hfsm_behaviours.room.stations import room_ties
from hfsm_behaviours.tararc.formulas import PAPER, Coefficients
from hfsm_behaviours.tararc.plan import Plan, make_plan

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
    `after`), the place beside the free side of a table with no room to stand at its other side
    (`cramped.free_place`: `free`, [] when both sides have room), and every robot's colour as it
    said it (-1: not said), for a robot to look for its partner."""
    tables = tables_of(tasks)
    if len(states) < PAIR * len(tables):
        raise ValueError(f"{len(states)} robots cannot make {len(tables)} pairs")
    plan = make_plan(states, tables, coeff, room_ties(states, tables))
    width, depth = float(room["width"]), float(room["depth"])
    ways = claim_walls(tables, width, depth, reach)
    after = turns(ways, tables, reach)
    plan["tables"] = {t["id"]: {**t, "toward": list(ways[t["id"]].toward), "after": after[t["id"]],
                                "corridor": _rect(ways[t["id"]].corridor),
                                "free": free_place(t, width, depth)} for t in tables}
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
