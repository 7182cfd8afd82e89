"""Primitives of the room-clearing team (machines/clear_room*.yaml): the plan of pairs, a robot's job
in it, the team's news (robots lost, tables done, dropped tables seen) and where a dropped table is.

Pure of any world: they hear, say and compute with `hfsm_behaviours.room`, so they run in world `none`.
"""

from __future__ import annotations

import math
from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm.runtime.program import span_ticks
from hfsm_behaviours.room.frames import ahead, at_wall, relocalise, to_local, to_room
from hfsm_behaviours.room.plan import drawn, job_of, make_room_plan, unmanned
from hfsm_behaviours.teamwork.plans import coefficients_from


@primitive(outcomes=["allocated"], outputs=["plan"])
def room_allocate(ctx: Context, *, mine: dict[str, Any], heard: dict[str, Any], tasks: list[Any],
                  room: dict[str, Any], coefficients: dict[str, Any], reach: float = 0.5) -> Outcome:
    """TARARC's groups, one per table of `tasks` (difficulty from the table's size), agents competing
    for the tables, and each table's claimed wall (corridors `reach` m wider than the table each side)."""
    states = {**heard, ctx.agent: mine}
    plan = make_room_plan(states, tasks, room, coefficients_from(coefficients), reach)
    return Outcome("allocated", plan=plan)


@primitive(outcomes=["assigned", "excluded"], outputs=["job", "drawn"])
def room_assign(ctx: Context, *, plan: dict[str, Any], lost: list[Any], done: list[Any], seen: dict[str, Any],
                start: dict[str, Any], spent: list[Any] | None = None,
                sliding: list[Any] | None = None, where: dict[str, Any] | None = None) -> Outcome:
    """This robot's job after the robots `lost` and the tables `done`, a dropped table where a
    survivor `seen` it, on a channel no `spent` pairing used, no helper lent to a table a survivor
    is `sliding` alone; `table` and `toward` in its own start frame (from `start`, where it was told
    it was placed); `turn`: the tables not yet done that its table waits for (their ways meet,
    `claims.turns`), but for a table no pair is left for (`unmanned`: it would be waited for until the
    room's limit). `excluded` when a teammate took this robot for lost. `drawn`: what the monitor
    draws of this robot's belief (`plan.drawn`: claimed corridors, its table, teammates `where` they
    last said they stood)."""
    where = {str(t): [float(v["x"]), float(v["y"])] for t, v in seen.items()}
    news = ([str(r) for r in lost], [str(t) for t in done], [str(c) for c in spent or []],
            [str(e) for e in sliding or []])
    job = job_of(plan, ctx.agent, news[0], news[1], where, news[2], news[3])
    if job is None:
        return Outcome("excluded", job={}, drawn={})
    after = plan["tables"][job["table"]].get("after", []) if job["table"] else []
    skip = set(news[1]) | set(unmanned(plan, *news))
    local = {"table_local": to_local(start, job["at"]) if job["at"] else [],
             "toward_local": to_local(start, job["toward"]) if job["toward"] else [],
             "turn": [t for t in after if t not in skip]}
    shown = drawn(plan, job, [str(t) for t in done], where or {})
    return Outcome("assigned", job={**job, **local}, drawn=shown)


@primitive(outcomes=["located"], outputs=["seen"])
def room_locate(ctx: Context, *, seen: dict[str, Any], table: str, start: dict[str, Any],
                pose: dict[str, Any],
                table_at: list[Any] | None = None, reach: float = 0.55) -> Outcome:
    """Where this robot, left with a dropped `table`, believes it is, in the room's frame, added to
    `seen`: `table_at` (its own estimate, start frame) when it has one, else `reach` m ahead of it
    (it faced the table it held)."""
    local = [float(v) for v in table_at] if table_at else ahead(pose, reach)
    x, y = to_room(start, local)
    sight = {"x": x, "y": y, "t": round(ctx.time, 6), "by": ctx.agent}
    return Outcome("located", seen={**seen, table: sight})


def _newer(a: dict[str, Any], b: dict[str, Any]) -> bool:
    return (float(a["t"]), str(a["by"])) > (float(b["t"]), str(b["by"]))


@primitive(outcomes=["changed"], outputs=["lost", "done", "seen", "spent", "sliding", "where"])
def room_watch(ctx: Context, *, team: list[Any], lost: list[Any], done: list[Any], seen: dict[str, Any],
               spent: list[Any] | None = None, sliding: list[Any] | None = None, silence: float = 5.0,
               message: str = "room_alive", where: dict[str, Any] | None = None) -> Outcome:
    """Listen to the team's heartbeats (`message`, said with data {lost, done, seen, spent, sliding})
    until the team knows more than given: a robot silent for `silence` s or said lost, a table said
    done, a dropped table seen later, a pairing spent, a table slid alone. Each is a set that only
    grows (a later sighting replaces an earlier one), so robots that heard the same news, in any
    order, agree. `where`: where each robot last said it stood (a heartbeat's `pose` from its `start`,
    room_pulse), in the room's frame: kept, not news."""
    known_where = {str(r): [float(p[0]), float(p[1])] for r, p in (where or {}).items()}
    known_lost, known_done = {str(r) for r in lost}, {str(t) for t in done}
    known_spent = {str(c) for c in spent or []}
    known_sliding = {str(e) for e in sliding or []}
    known_seen = {str(t): dict(v) for t, v in seen.items()}
    watched = {str(r) for r in team} - known_lost - {ctx.agent}
    heard = dict.fromkeys(watched, ctx.tick)
    quiet = span_ticks(silence, ctx.dt)
    given = (set(known_lost), set(known_done), {t: dict(v) for t, v in known_seen.items()}, set(known_spent),
             set(known_sliding))

    def news() -> bool:
        while (m := ctx.receive(message)) is not None:
            if m.sender in heard:
                heard[m.sender] = ctx.tick
            pose, start = m.data.get("pose"), m.data.get("start")
            if pose and start:
                known_where[m.sender] = to_room(start, [pose["x"], pose["y"]])
            data = m.data.get("data", {})
            known_lost.update(str(r) for r in data.get("lost", []))
            known_done.update(str(t) for t in data.get("done", []))
            known_spent.update(str(c) for c in data.get("spent", []))
            known_sliding.update(str(e) for e in data.get("sliding", []))
            for table, sight in data.get("seen", {}).items():
                mine = known_seen.get(str(table))
                if mine is None or _newer(sight, mine):
                    known_seen[str(table)] = dict(sight)
        known_lost.update(r for r, tick in heard.items() if ctx.tick - tick >= quiet)
        return (known_lost, known_done, known_seen, known_spent, known_sliding) != given

    ctx.wait_until(news)
    return Outcome("changed", lost=sorted(known_lost), done=sorted(known_done),
                   seen=dict(sorted(known_seen.items())), spent=sorted(known_spent),
                   sliding=sorted(known_sliding), where=dict(sorted(known_where.items())))


@primitive(outcomes=["relocalised", "kept"], outputs=["start"])
def room_relocalise(ctx: Context, *, start: dict[str, Any], pose: dict[str, Any], seen: list[Any] | None,
                    table: dict[str, Any], near: float = 1.2, shift: float = 1.0, turn: float = 20.0
                    ) -> Outcome:
    """After its table reached its wall, where the robot started, corrected by that table: its place
    there is known (its claimed way, `at_wall`) and the robot sees it (`seen`: in.tables_in_view,
    own frame). The table seen nearest the robot within `near` m counts; a correction larger than
    `shift` m or `turn` degrees is not believed (another table, a bad view): `kept`."""
    here = (float(pose["x"]), float(pose["y"]))
    views = [v for v in seen or [] if not v.get("clipped")] or list(seen or [])
    if not views:
        return Outcome("kept", start=start)
    view = min(views, key=lambda v: math.dist(here, (float(v["x"]), float(v["y"]))))
    if math.dist(here, (float(view["x"]), float(view["y"]))) > near:
        return Outcome("kept", start=start)
    new = relocalise(start, [view["x"], view["y"]], float(view["heading"]), at_wall(table),
                     float(table.get("yaw", 0)))
    moved = math.dist((new["x"], new["y"]), (float(start["x"]), float(start["y"])))
    if moved > shift or abs(new["yaw"] - float(start["yaw"])) > turn:
        return Outcome("kept", start=start)
    return Outcome("relocalised", start=new)
