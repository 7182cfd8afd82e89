"""Primitives of a room robot's walk to its table (machines/room_carry.yaml): the way there, planned
around what the team knows (hfsm_behaviours.room.walks), and the right of way between walkers, over the
radio. Pure of any world: walking it is go_along's."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.room.aside import aside
from hfsm_behaviours.room.claims import footprint
from hfsm_behaviours.room.frames import to_local, to_room
from hfsm_behaviours.room.walks import (
    Point,
    Scene,
    conflict,
    corridor,
    crowd,
    goes_first,
    head,
    left_of,
    place_for,
    table_where,
    way_to,
)

WALK = "room_walk"


def _scene(tables: dict[str, Any], done: list[Any], seen: dict[str, Any], robots: list[Point],
           room: dict[str, Any]) -> Scene:
    width, depth = float(room["width"]), float(room["depth"])
    finished = {str(t) for t in done}
    tops, lanes = [], []
    for tid, t in sorted(tables.items()):
        sight = seen.get(tid)
        at = table_where(t, tid in finished, [sight["x"], sight["y"]] if sight else None)
        tops.append(footprint(t, 0.0, at))
        if tid not in finished:
            lanes.append(corridor(t, width, depth))
    return Scene(width, depth, tuple(tops), tuple(lanes), tuple(robots))


def _said(where: dict[str, Any] | None, starts: dict[str, Any] | None) -> dict[str, Point]:
    """Where each robot last said it stands (`where`, room frame), else where it started (`starts`)."""
    said = {str(r): (float(p["x"]), float(p["y"])) for r, p in (starts or {}).items()}
    said.update({str(r): (float(p[0]), float(p[1])) for r, p in (where or {}).items()})
    return said


@primitive(outcomes=["walk", "here", "boxed"], outputs=["path", "walk", "face", "length", "standing"])
def room_route(ctx: Context, *, job: dict[str, Any], start: dict[str, Any], pose: dict[str, Any],
               tables: dict[str, Any], room: dict[str, Any], done: list[Any] | None = None,
               seen: dict[str, Any] | None = None, where: dict[str, Any] | None = None,
               starts: dict[str, Any] | None = None, near: float = 0.8, wait: bool = False) -> Outcome:
    """The way to this robot's place beside its table (`job`: table, at), planned round the tables,
    their claimed corridors and the robots standing where they last said they were (`where`: {robot:
    [x, y]}, room frame; else where they started, `starts`: {robot: {x, y}}); `here` when the robot
    is within `near` m of that place. `path`: the waypoints in its own start frame; `walk`: where it
    stands then the waypoints, in the room's frame (what it says to the other walkers); `face`: the
    table, in its own start frame; `length`: the way's metres (0 when here); `standing`: where the
    other robots stand as it knows it ({robot: [x, y]}, room frame: for room_give_way). Where no way
    keeps `walks.TIGHT` m off the robots standing either, `boxed` with `wait` (the robot waits for
    them to move and plans again), else a way round the tables alone (`walks.way_to`)."""
    me_local = [float(pose["x"]), float(pose["y"])]
    x, y = to_room(start, me_local)
    me = (x, y)
    table = tables[str(job["table"])]
    told = job.get("at") or [table["x"], table["y"]]
    at = (float(told[0]), float(told[1]))
    said = _said(where, starts)
    others = [p for r, p in sorted(said.items()) if r != ctx.agent]
    mate = said.get(str(job.get("partner", "")))
    size = (float(room["width"]), float(room["depth"])) if room else None
    # the table walked to is not in the way of its own place
    rest = {k: v for k, v in tables.items() if k != str(job["table"])}
    scene = _scene(rest, done or [], seen or {}, others, room)
    goal = place_for(table, at, me, others, partner=mate, leads=job.get("role") != "assistant", room=size,
                     tops=scene.tables)
    if math.dist(me, goal) <= near:
        return Outcome("here", path=[], walk=[], face=to_local(start, at), length=0.0, standing={})
    scene = replace(scene, tables=(*scene.tables, footprint(table, 0.0, at)))
    points = way_to(scene, me, goal, wait)
    if points is None:
        return Outcome("boxed", path=[], walk=[], face=to_local(start, at), length=0.0, standing={})
    length = sum(math.dist(a, b) for a, b in zip([me, *points], points, strict=False))
    return Outcome("walk", path=[to_local(start, p) for p in points], face=to_local(start, at),
                   walk=[[round(p[0], 4), round(p[1], 4)] for p in [me, *points]], length=round(length, 3),
                   standing={r: [p[0], p[1]] for r, p in sorted(said.items()) if r != ctx.agent})


@primitive(outcomes=["aside"], outputs=["spot"])
def room_aside(ctx: Context, *, job: dict[str, Any], start: dict[str, Any], pose: dict[str, Any],
               tables: dict[str, Any], room: dict[str, Any], done: list[Any] | None = None,
               seen: dict[str, Any] | None = None, where: dict[str, Any] | None = None,
               starts: dict[str, Any] | None = None) -> Outcome:
    """Where this robot waits (`spot`, [x, y] in its own start frame): a robot standing in a claimed
    corridor of a table not yet done, or beside another table still to be carried (its own, for a
    leader or an assistant, is not another), steps to the nearest point out of their way
    (hfsm_behaviours.room.aside, round the tables and the robots where the team believes them);
    any other robot waits where it stands."""
    here = [float(pose["x"]), float(pose["y"])]
    if not tables or not room:
        return Outcome("aside", spot=here)
    me = to_room(start, here)
    said = _said(where, starts)
    others = [p for r, p in sorted(said.items()) if r != ctx.agent]
    finished = {str(t) for t in done or []}
    own = str(job.get("table", "")) if job.get("role") in ("leader", "assistant") else ""
    scene = _scene(tables, done or [], seen or {}, others, room)
    # the scene's tops are the tables' in sorted order, where the team believes them
    busy = tuple(top for tid, top in zip(sorted(tables), scene.tables, strict=True)
                 if tid not in finished and tid != own)
    spot = aside(scene, (me[0], me[1]), busy=busy)
    if spot == (me[0], me[1]):
        return Outcome("aside", spot=here)
    return Outcome("aside", spot=[round(v, 6) for v in to_local(start, spot)])


@primitive(outcomes=["clear", "timeout"], outputs=["since", "crowd", "waited"])
def room_give_way(ctx: Context, *, walk: list[Any], standing: dict[str, Any] | None = None,
                  every: float = 1.0, quiet: float = 2.5, limit: float = 90.0) -> Outcome:
    """Say this walk (`room_walk`, every `every` s) and wait while another walker with the right of
    way (said its walk first, then fewer robots `standing` in its way ({robot: [x, y]}, room frame:
    `walks.crowd`; in a packed start the robots on the outside go first), then the smaller id) still
    says it (heard within `quiet` s) and what is
    left of its way comes near the first metres of this one (`walks.conflict`, `walks.head`): all of
    its way until it says where it is (its `pose` and `start` as room_pulse says them), then only the
    rest of it from there on, so that a walker waits only until the first has passed or is ahead
    of it; for `limit` s at most.
    `since`: when this robot first said its walk (the walkers it meets later give way to it), said
    with its `crowd`; `waited`: the seconds it waited."""
    since = round(ctx.time, 6)
    way = [(float(p[0]), float(p[1])) for p in walk]
    mine = head(way)
    others = [(float(p[0]), float(p[1])) for r, p in sorted((standing or {}).items()) if r != ctx.agent]
    many = crowd(way, others)
    heard: dict[str, tuple[float, int, list[Point], float]] = {}
    next_say = ctx.time

    def free() -> bool:
        nonlocal next_say
        if ctx.time >= next_say:
            ctx.send(WALK, keep="last", round=0, data={"walk": walk, "since": since, "crowd": many})
            next_say = ctx.time + every
        while (m := ctx.receive(WALK)) is not None:
            data = m.data.get("data", {})
            if m.sender != ctx.agent and data.get("walk"):
                path = [(float(p[0]), float(p[1])) for p in data["walk"]]
                pose, start = m.data.get("pose"), m.data.get("start")
                if pose and start:
                    x, y = to_room(start, [pose["x"], pose["y"]])
                    path = left_of(path, (x, y))
                heard[m.sender] = (float(data.get("since", 0.0)), int(data.get("crowd", 0)), path, ctx.time)
        if ctx.time - since < every + ctx.dt:  # hear the others' walks first
            return False
        return not any(ctx.time - t <= quiet and goes_first((s, n, r), (since, many, ctx.agent))
                       and conflict(mine, p) for r, (s, n, p, t) in heard.items())

    clear = ctx.wait_until(free, timeout=limit)
    waited = round(ctx.time - since, 6)
    return Outcome("clear" if clear else "timeout", since=since, crowd=many, waited=waited)
