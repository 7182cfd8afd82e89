"""Grouping ties in a room: robots with no history all have relevance 0, and TARARC's greedy grouping
then took partners by id ("r1" with "r10"), sending pairs across the room. Ties go by distance
instead (the paper's eq. 4 costs distance too): every robot has a *station*, the table nearest it
where it was placed; a group is seeded by the robot nearest its station, and its partners are, in
order, the robots of the same station, then robots standing at no table, then robots standing at
another table (within `stand` m of it: that table's pair), each by distance to the seed's station.

Computed from the states every robot heard (positions said in the share) and the task list, so
every robot groups the same.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from behaviours.tararc.grouping import Ties

STAND = 1.5  # metres from a table's centre within which a robot stands at it (its pair's place: 1.2 m)


def stations(robots: Mapping[str, Mapping[str, Any]], tables: Sequence[Mapping[str, Any]]
             ) -> dict[str, tuple[str, float]]:
    """Every robot's nearest table and its distance to it (ties by table id)."""
    out = {}
    for r, s in robots.items():
        here = (float(s["x"]), float(s["y"]))
        out[r] = min(((str(t["id"]), math.dist(here, (float(t["x"]), float(t["y"])))) for t in tables),
                     key=lambda td: (td[1], td[0]))
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
        rank = 0.0 if own == home else (1.0 if gap > stand else 2.0)
        return (rank, round(math.dist(at[robot], where[home]), 9))

    return Ties(seed=lambda r: round(near[r][1], 9), partner=partner)
