"""The pure steps of the room's recovery decisions (`hfsm_behaviours.room.recovery`), which
machines/room_assign.yaml calls in turn: the slides going on, who replaces whom, who is lent,
whether a pair is left, this robot's place, its pairing's channel, its job. No radio, no world."""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.room import recovery
from hfsm_behaviours.room.frames import to_local
from hfsm_behaviours.room.plan import drawn


def _strs(values: list[Any] | None) -> list[str]:
    return [str(v) for v in values or []]


@primitive(outcomes=["found"], outputs=["partners"])
def room_slides(ctx: Context, *, lost: list[Any], done: list[Any], spent: list[Any],
                sliding: list[Any]) -> Outcome:
    """The failed partners of the slides still going on (a survivor, not lost, slides its table
    alone, not yet done, and has not said its pairing spent): they stay in their group, so that no
    helper is lent to that table."""
    partners = recovery.sliding_partners(_strs(lost), _strs(done), _strs(spent), _strs(sliding))
    return Outcome("found", partners=sorted(partners))


@primitive(outcomes=["replaced"], outputs=["groups"])
def room_replace(ctx: Context, *, plan: dict[str, Any], lost: list[Any], kept: list[Any]) -> Outcome:
    """Who replaces whom after the robots `lost` (but those `kept` in their group): TARARC's 7a and
    7b, a lost leader's place to its assistant, a lost assistant's to a spare of its group."""
    gone = sorted(set(_strs(lost)) - set(_strs(kept)))
    return Outcome("replaced", groups=recovery.replaced(plan, gone))


@primitive(outcomes=["lent", "kept"], outputs=["groups"])
def room_lend(ctx: Context, *, plan: dict[str, Any], groups: list[Any], done: list[Any]) -> Outcome:
    """Who is lent: a group left short of a pair, its table not done, borrows the robots of groups
    whose tables are `done`, nearest first; two lone robots of short tables pair up. `kept`: no
    robot moved."""
    after = recovery.lent(plan, groups, _strs(done))
    return Outcome("lent" if after != groups else "kept", groups=after)


@primitive(outcomes=["counted"], outputs=["gone", "tries"])
def room_tried(ctx: Context, *, done: list[Any], spent: list[Any], tables: dict[str, Any]) -> Outcome:
    """The tables (of the plan's `tables`) the team gives up: not `done`, and `recovery.TRIES`
    pairings or more `spent` without them at their wall. `gone`: their ids (their robots are free
    for the other tables); `tries`: how many pairings each had."""
    counts = recovery.tried(_strs(done), _strs(spent), sorted(str(t) for t in tables))
    return Outcome("counted", gone=sorted(counts), tries=counts)


@primitive(outcomes=["paired", "stuck"], outputs=["stuck"])
def room_stranded(ctx: Context, *, groups: list[Any], done: list[Any], sliding: bool,
                  tries: dict[str, Any] | None = None) -> Outcome:
    """`stuck` when no pair is left for a table not yet done and nobody is `sliding` one alone, or
    when only tables given up are left (`tries`: room_tried's): `stuck` says which table and why
    (the room ends honestly)."""
    gone = {str(k): int(v) for k, v in (tries or {}).items()}
    left = recovery.stranded(groups, _strs(done), sliding, gone)
    return Outcome("stuck" if left else "paired", stuck=left)


@primitive(outcomes=list(recovery.ROLES), outputs=["place"])
def room_role(ctx: Context, *, groups: list[Any], done: list[Any]) -> Outcome:
    """This robot's place in the groups: its group's agent leads, its first other member assists,
    the others are spares; `idle` when its table is done or it is in no group. `place`: {role,
    group, table, leader, assistant}."""
    place = recovery.place_of(ctx.agent, groups, _strs(done))
    return Outcome(place["role"], place=place)


@primitive(outcomes=["chosen"], outputs=["channel"])
def room_channel(ctx: Context, *, table: str, leader: str, assistant: str, spent: list[Any]) -> Outcome:
    """When a pairing is spent: the pair's channel, numbered by the tries on this table that both
    robots said `spent`, so that a pair tries again on a new channel once both know the last try
    is over."""
    return Outcome("chosen", channel=recovery.channel_of(table, leader, assistant, _strs(spent)))


@primitive(outcomes=["assigned"], outputs=["job", "drawn"])
def room_job(ctx: Context, *, plan: dict[str, Any], place: dict[str, Any], channel: str, lost: list[Any],
             done: list[Any], seen: dict[str, Any], start: dict[str, Any], stuck: dict[str, Any],
             where: dict[str, Any] | None = None, spent: list[Any] | None = None) -> Outcome:
    """The job the machines carry (`room.recovery`): role, table, partner, channel, where the table
    is believed to be (`seen` by a survivor, else the plan's) and its wall; `table_local` and
    `toward_local` in this robot's start frame (`start`); `turn`, the tables not yet done that its
    table waits for (`claims.turns`); `slide`, who slides a cramped table alone (`spent`: the
    pairings spent, "CHANNEL/ROBOT"). `drawn`: what the monitor draws of this robot's belief."""
    sightings = {str(t): [float(v["x"]), float(v["y"])] for t, v in seen.items()}
    finished = _strs(done)
    job = recovery.job_in(plan, ctx.agent, place, channel, _strs(lost), finished, sightings,
                          {str(k): str(v) for k, v in stuck.items()}, _strs(spent))
    after = plan["tables"][job["table"]].get("after", []) if job["table"] else []
    local = {"table_local": to_local(start, job["at"]) if job["at"] else [],
             "toward_local": to_local(start, job["toward"]) if job["toward"] else [],
             "turn": [t for t in after if t not in set(finished)]}
    return Outcome("assigned", job={**job, **local}, drawn=drawn(plan, job, finished, sightings))
