"""Tables with no room to stand at one long side: one robot slides them alone from the other.

The paper's pair lifts a table from the middles of its two long sides, and the assistant walks round
the table's corners `margin` m clear to reach its side. A table whose long side stands closer than
`ROOM` m to a wall (along that side's outward normal) leaves no room there: the robot sent to that
side walked round the table for minutes, pushing it against the wall (generated room open-537, the
side 0.43 m from the wall). Such a table is *cramped*: one robot of its pair slides it alone along
its long axis to its claimed wall (drag_table, as a survivor does), standing at the middle of the
free side; the other waits. Who slides is a pure function of the plan and the pairings spent, so
both robots of the pair agree: the one told it started nearer the free side's place first (ties:
the leader); once it said its try spent, the other; once both did, the pair's channel changes and
the first slides again.

Everything here is pure and in the room's frame.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from hfsm_behaviours.room.claims import GAP, wall_hit

Point = tuple[float, float]
ROOM = 0.7  # metres from the middle of a long side to the wall ahead of it needed to stand and walk there


def side_room(table: Mapping[str, Any], width: float, depth: float) -> tuple[float, float]:
    """Metres from the middle of each long side (+normal, -normal) to the wall that side faces."""
    yaw = math.radians(float(table.get("yaw", 0.0)))
    nx, ny = -math.sin(yaw), math.cos(yaw)
    half = float(table.get("width", 0.5)) / 2
    x, y = float(table["x"]), float(table["y"])
    room = [wall_hit(x + s * half * nx, y + s * half * ny, s * nx, s * ny, width, depth) for s in (1, -1)]
    return room[0], room[1]


def free_place(table: Mapping[str, Any], width: float, depth: float, room: float = ROOM,
               gap: float = GAP) -> list[float]:
    """The place (`gap` m from the centre line, as walks.places) beside the free long side of a
    cramped table ([x, y]); [] when both sides have room (or neither: it is carried as a pair)."""
    ahead = side_room(table, width, depth)
    tight = [r < room for r in ahead]
    if tight[0] == tight[1]:
        return []
    yaw = math.radians(float(table.get("yaw", 0.0)))
    s = -1 if tight[0] else 1
    x, y = float(table["x"]) - s * gap * math.sin(yaw), float(table["y"]) + s * gap * math.cos(yaw)
    return [round(x, 6), round(y, 6)]


def slider_of(free: Sequence[float], leader: str, assistant: str, starts: Mapping[str, Mapping[str, Any]],
              channel: str, spent: Sequence[str]) -> str:
    """Which robot of the pair slides the cramped table on `channel`: the one told it started nearer
    the `free` place (ties: the leader), unless it said this try spent ("CHANNEL/ROBOT" in `spent`),
    then the other."""
    def far(robot: str) -> float:
        at = starts.get(robot, {})
        return round(math.dist((float(at.get("x", 0.0)), float(at.get("y", 0.0))), (free[0], free[1])), 6)

    first, second = sorted((leader, assistant), key=lambda r: (far(r), r != leader))
    return second if f"{channel}/{first}" in set(spent) else first


def slide_job(tables: Mapping[str, Any], place: Mapping[str, Any], me: str, starts: Mapping[str, Any],
              channel: str, spent: Sequence[str]) -> str:
    """'me' when this robot slides its cramped table alone, 'partner' when its partner does, ''
    when its table is carried as a pair (or it has no pair)."""
    if place.get("role") not in ("leader", "assistant") or not place.get("table"):
        return ""
    free = tables[str(place["table"])].get("free", [])
    if not free or not place.get("leader") or not place.get("assistant"):
        return ""
    slider = slider_of(free, str(place["leader"]), str(place["assistant"]), starts, channel, spent)
    return "me" if slider == me else "partner"
