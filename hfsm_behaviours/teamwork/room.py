"""Primitives of the room-clearing team (machines/clear_room*.yaml): the plan of pairs, the team's news
(robots lost, tables done, dropped tables seen) and where a dropped table is. A robot's job in the
plan is machines/room_assign.yaml's (over `teamwork.recovery`).

Pure of any world: they hear, say and compute with `hfsm_behaviours.room`, so they run in world `none`.
"""

from __future__ import annotations

import math
from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm.runtime.program import span_ticks
from hfsm_behaviours.room import news as team_news
from hfsm_behaviours.room.claims import footprint
from hfsm_behaviours.room.frames import ahead, at_wall, relocalise, to_room
from hfsm_behaviours.room.plan import make_room_plan
from hfsm_behaviours.teamwork.plans import coefficients_from


@primitive(outcomes=["allocated"], outputs=["plan"])
def room_allocate(ctx: Context, *, mine: dict[str, Any], heard: dict[str, Any], tasks: list[Any],
                  room: dict[str, Any], coefficients: dict[str, Any], reach: float = 0.5) -> Outcome:
    """TARARC's groups, one per table of `tasks` (difficulty from the table's size), agents competing
    for the tables, and each table's claimed wall (corridors `reach` m wider than the table each side)."""
    states = {**heard, ctx.agent: mine}
    plan = make_room_plan(states, tasks, room, coefficients_from(coefficients), reach)
    return Outcome("allocated", plan=plan)


def _xy(point: list[Any]) -> tuple[float, float]:
    return float(point[0]), float(point[1])


@primitive(outcomes=["located"], outputs=["seen"])
def room_locate(ctx: Context, *, seen: dict[str, Any], table: str, start: dict[str, Any],
                pose: dict[str, Any],
                table_at: list[Any] | None = None, reach: float = 0.55,
                tables: dict[str, Any] | None = None, done: list[Any] | None = None,
                margin: float = 0.3, believed: list[Any] | None = None, same: float = 0.02) -> Outcome:
    """Where this robot, left with a dropped `table`, believes it is, in the room's frame, added to
    `seen`: `table_at` (its own estimate, start frame) when it has one, else `reach` m ahead of it
    (it faced the table it held). A place within `margin` m of a table already at its wall (`done`,
    of the plan's `tables`) is that table, not this one (the robot saw the nearest table and took it
    for its own): the team's sighting is left as it was. So is it when `table_at` is, within `same`
    m, where the job had the table (`believed`, start frame): move_furniture gives that back when
    the robot sees no table at the end, and saying it again, later, would outweigh a partner that
    did see where the table went (held-out rooms walls-40000, mixed-40001)."""
    if table_at and believed and math.dist(_xy(table_at), _xy(believed)) <= same:
        return Outcome("located", seen=seen)
    local = [float(v) for v in table_at] if table_at else ahead(pose, reach)
    x, y = to_room(start, local)
    for tid in sorted(str(t) for t in done or []):
        other = (tables or {}).get(tid)
        if tid != table and other is not None:
            wx, wy = at_wall(other)
            if footprint(other, 0.0, (wx, wy)).contains((x, y), margin):
                return Outcome("located", seen=seen)
    sight = {"x": x, "y": y, "t": round(ctx.time, 6), "by": ctx.agent}
    return Outcome("located", seen={**seen, table: sight})


@primitive(outcomes=["listening"], outputs=["news"])
def room_news(ctx: Context, *, team: list[Any], lost: list[Any], done: list[Any], seen: dict[str, Any],
              spent: list[Any] | None = None, sliding: list[Any] | None = None, silence: float = 5.0,
              where: dict[str, Any] | None = None) -> Outcome:
    """The news this robot holds as it starts to listen (machines/room_watch.yaml): what the team
    knows, where each robot last said it stood, every teammate not lost heard now; a teammate
    silent for `silence` s is lost."""
    known = {"lost": lost, "done": done, "seen": seen, "spent": spent or [], "sliding": sliding or []}
    return Outcome("listening", news=team_news.news_of(ctx.agent, team, known, where or {}, ctx.tick,
                                                  span_ticks(silence, ctx.dt)))


@primitive(outcomes=["heard"], outputs=["news"])
def room_hear(ctx: Context, *, news: dict[str, Any], heard: list[Any]) -> Outcome:
    """Teammates' heartbeats merged into the news, oldest first (`heard`: wait_for's `messages`, each
    its `sender`, its news `data` and where it stands, `pose` from its `start`, room frame): each
    sender heard now, its news added (a later sighting replaces an earlier one)."""
    for message in heard:
        news = team_news.hear(news, str(message.get("sender", "")), message.get("data"), message.get("pose"),
                              message.get("start"), ctx.tick)
    return Outcome("heard", news=news)


@primitive(outcomes=["changed", "same"], outputs=["news", "wake", "lost", "done", "seen", "spent", "sliding",
                                                  "where"])
def room_settle(ctx: Context, *, news: dict[str, Any]) -> Outcome:
    """The teammates silent for `silence` s added to the lost; `changed` when the team knows more
    than it was given. `wake`: seconds until the next teammate would fall silent."""
    new, changed = team_news.settle(news, ctx.tick)
    wake = round(team_news.wake(new, ctx.tick) * ctx.dt, 9)
    return Outcome("changed" if changed else "same", news=new, wake=wake, **team_news.told(new))


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
