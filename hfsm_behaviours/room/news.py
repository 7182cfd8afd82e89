"""The room team's news as data a machine carries (machines/room_watch.yaml): what this robot knows
(robots lost, tables done, dropped tables seen, pairings spent, slides), where each teammate last
said it stood, and when each was last heard. Pure: the tick is the caller's.

Each set only grows (a later sighting replaces an earlier one), so robots that heard the same news,
in any order, agree.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hfsm_behaviours.room.frames import to_room

SETS = ("lost", "done", "spent", "sliding")


def news_of(me: str, team: list[Any], known: Mapping[str, Any], where: Mapping[str, Any], tick: int,
            quiet: int) -> dict[str, Any]:
    """The news as given (`known`: {lost, done, seen, spent, sliding}), every teammate not lost
    heard now, `quiet` ticks of silence making a robot lost."""
    sets = {k: sorted({str(v) for v in known.get(k) or []}) for k in SETS}
    seen = {str(t): dict(v) for t, v in sorted((known.get("seen") or {}).items())}
    watched = sorted({str(r) for r in team} - set(sets["lost"]) - {me})
    return {**sets, "seen": seen, "where": {str(r): [float(p[0]), float(p[1])] for r, p in where.items()},
            "heard": dict.fromkeys(watched, tick), "quiet": quiet, "given": {**sets, "seen": seen}}


def _newer(a: Mapping[str, Any], b: Mapping[str, Any]) -> bool:
    """The later sighting, then by robot, then by place: a total order, so news merge in any order."""
    return _order(a) > _order(b)


def _order(sight: Mapping[str, Any]) -> tuple[float, str, float, float]:
    return float(sight["t"]), str(sight["by"]), float(sight.get("x", 0.0)), float(sight.get("y", 0.0))


def hear(news: Mapping[str, Any], sender: str, data: Any, pose: Any, start: Any, tick: int) -> dict[str, Any]:
    """A heartbeat merged: its sender heard now, where it stands (`pose` from its `start`, in the
    room's frame), and its news (`data`) added to this robot's."""
    new: dict[str, Any] = {**news, "heard": dict(news["heard"]), "where": dict(news["where"]),
                           "seen": dict(news["seen"])}
    if sender in new["heard"]:
        new["heard"][sender] = tick
    if pose and start:
        new["where"][sender] = to_room(start, [pose["x"], pose["y"]])
    said = data if isinstance(data, Mapping) else {}
    for key in SETS:
        new[key] = sorted(set(new[key]) | {str(v) for v in said.get(key, [])})
    for table, sight in said.get("seen", {}).items():
        mine = new["seen"].get(str(table))
        if mine is None or _newer(sight, mine):
            new["seen"][str(table)] = dict(sight)
    new["seen"] = dict(sorted(new["seen"].items()))
    return new


def settle(news: Mapping[str, Any], tick: int) -> tuple[dict[str, Any], bool]:
    """The robots silent for `quiet` ticks added to the lost; whether the team now knows more than
    it was given."""
    silent = {r for r, last in news["heard"].items() if tick - int(last) >= news["quiet"]}
    new = {**news, "lost": sorted(set(news["lost"]) | silent)}
    known = {k: new[k] for k in (*SETS, "seen")}
    return new, known != news["given"]


def wake(news: Mapping[str, Any], tick: int) -> int:
    """Ticks until the next teammate not yet lost would fall silent (at least one)."""
    ends = [int(last) + news["quiet"] - tick for r, last in news["heard"].items() if r not in news["lost"]]
    return max(1, min(ends)) if ends else int(news["quiet"])


def told(news: Mapping[str, Any]) -> dict[str, Any]:
    """The outputs: the news and where each robot last said it stood."""
    return {**{k: news[k] for k in (*SETS, "seen")}, "where": dict(sorted(news["where"].items()))}
