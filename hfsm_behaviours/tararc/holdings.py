"""What one robot holds of TARARC's state exchange, as data a machine carries (machines/tararc_exchange.yaml).

Pure: no radio, no clock. The time is the tick the caller gives. A holding is a dict:

    {"me": "r0", "team": ["r1", "r2"] | None,   # None: open, the team is whoever is heard
     "held": {robot: data},                    # this robot's data and every teammate's it heard
     "says": {robot: [robots]},                # what each teammate last said it holds
     "last": {robot: tick},                    # when each teammate was last heard
     "start": tick, "quiet": ticks | None}     # silent for `quiet` ticks: failed
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

Holding = dict[str, Any]


def holding(me: str, data: Any, team: list[Any] | None, start: int, quiet: int | None) -> Holding:
    """What a robot holds as the exchange starts: its own data."""
    return {"me": me, "team": None if team is None else sorted({str(r) for r in team} - {me}),
            "held": {me: data}, "says": {}, "last": {}, "start": start, "quiet": quiet}


def _member(hold: Mapping[str, Any], robot: str) -> bool:
    return hold["team"] is None or robot in hold["team"] or robot == hold["me"]


def merge(hold: Mapping[str, Any], sender: str, said: Any, tick: int) -> tuple[Holding, bool]:
    """A teammate's copy `said` ({held: {robot: data}, team: [robots]}) merged into `hold`; whether
    this robot now holds more. A robot that could not meet its team takes the team the teammate
    met; copies from robots outside the team, and robots outside it that they hold, are dropped."""
    new: Holding = {**hold, "held": dict(hold["held"]), "says": dict(hold["says"]),
                    "last": dict(hold["last"])}
    held = said.get("held") if isinstance(said, Mapping) else None
    if not isinstance(held, Mapping):
        return new, False
    met = said.get("team")
    if new["team"] is None and isinstance(met, list):
        new["team"] = sorted(({str(r) for r in met} | {sender}) - {new["me"]})
    if sender == new["me"] or not _member(new, sender):
        return new, False
    new["last"][sender] = tick
    theirs = {str(r): d for r, d in held.items() if _member(new, str(r))}
    new["says"][sender] = sorted(theirs)
    more = {r: d for r, d in theirs.items() if r not in new["held"]}
    new["held"].update(more)
    new["held"] = dict(sorted(new["held"].items()))
    return new, bool(more)


def said(hold: Mapping[str, Any]) -> dict[str, Any]:
    """What the robot says: what it holds, and the team it met (when it met one)."""
    out: dict[str, Any] = {"held": dict(sorted(hold["held"].items()))}
    if hold["team"] is not None:
        out["team"] = sorted({*hold["team"], hold["me"]})
    return out


def silent(hold: Mapping[str, Any], robot: str, tick: int) -> bool:
    quiet = hold["quiet"]
    return quiet is not None and tick - int(hold["last"].get(robot, hold["start"])) >= quiet


def agreed(hold: Mapping[str, Any], tick: int) -> bool:
    """Every teammate is held or silent (open, until a teammate that met the team names it: `quiet`
    has passed), and every teammate held that still talks last said it holds exactly the robots
    this one holds."""
    if hold["team"] is None:
        if hold["quiet"] is None or tick - int(hold["start"]) < hold["quiet"]:
            return False
    elif any(r not in hold["held"] and not silent(hold, r, tick) for r in hold["team"]):
        return False
    mine = sorted(hold["held"])
    return all(hold["says"].get(r) == mine or silent(hold, r, tick) for r in hold["held"] if r != hold["me"])


def wake(hold: Mapping[str, Any], tick: int) -> int | None:
    """Ticks until time alone could change `agreed` (a teammate falls silent, an open robot's wait
    ends); None when nothing but a message can."""
    quiet = hold["quiet"]
    if quiet is None:
        return None
    ends = [int(hold["start"]) + quiet] if hold["team"] is None else []
    robots = set(hold["team"] or []) | set(hold["held"])
    ends += [int(hold["last"].get(r, hold["start"])) + quiet for r in robots - {hold["me"]}]
    later = [end - tick for end in ends if end > tick]
    return min(later) if later else None


def results(hold: Mapping[str, Any], tick: int) -> dict[str, Any]:
    """The exchange's outputs: `heard` (the teammates' data), `team` (their ids), `held` (`heard`
    with this robot's own) and `talking` (the teammates held that are not silent)."""
    heard = {r: d for r, d in sorted(hold["held"].items()) if r != hold["me"]}
    return {"heard": heard, "team": sorted(heard), "held": dict(sorted(hold["held"].items())),
            "talking": [r for r in heard if not silent(hold, r, tick)]}
