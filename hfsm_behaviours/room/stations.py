"""Grouping ties in a room: robots with no history all have relevance 0, and TARARC's greedy grouping
then took partners by id ("r1" with "r10"), sending pairs across the room. Ties go by distance
instead (the paper's eq. 4 costs distance too): every robot has a *station*, the table with the
place nearest it (a place: the middle of a long side, `claims.GAP` m out, where a pair stands; the
table's centre would give a robot at one table's side to a table whose end is a little nearer);
a group is seeded by the robot nearest its place, and its partners are, in order, the robots
standing at a place of the same station (within `stand` m of it), the other robots of that station,
robots of other stations standing at no place, then robots standing at another table's place (that
table's pair), each by distance to the seed's station.

Computed from the states every robot heard (positions said in the share) and the task list, so
every robot groups the same.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm_behaviours.room.claims import places
from hfsm_behaviours.tararc.grouping import Ties

STAND = 0.6  # metres from a place beside a table within which a robot stands at that table


def stations(robots: Mapping[str, Mapping[str, Any]], tables: Sequence[Mapping[str, Any]]
             ) -> dict[str, tuple[str, float]]:
    """Every robot's station: the table with the place nearest it, and its distance to that place
    (ties by table id)."""
    spots = [(str(t["id"]), p) for t in tables for p in places(t, (float(t["x"]), float(t["y"])))]
    out = {}
    for r, s in robots.items():
        here = (float(s["x"]), float(s["y"]))
        out[r] = min(((tid, math.dist(here, p)) for tid, p in spots), key=lambda td: (td[1], td[0]))
    return out


def room_ties(robots: Mapping[str, Mapping[str, Any]], tables: Sequence[Mapping[str, Any]],
              stand: float = STAND) -> Ties:
    """The tie-breaks of TARARC's grouping in a room (see the module's doc)."""
    if not tables:
        return Ties(seed=lambda r: 0.0, partner=lambda s, r: ())
    where = {str(t["id"]): (float(t["x"]), float(t["y"])) for t in tables}
    near = stations(robots, tables)
    at = {r: (float(s["x"]), float(s["y"])) for r, s in robots.items()}

    def partner(seed: str, robot: str) -> tuple[float, ...]:
        home, _ = near[seed]
        own, gap = near[robot]
        standing = gap <= stand
        rank = (0.0 if standing else 1.0) if own == home else (3.0 if standing else 2.0)
        return (rank, round(math.dist(at[robot], where[home]), 9))

    return Ties(seed=lambda r: round(near[r][1], 9), partner=partner)
