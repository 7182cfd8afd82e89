"""Hearing the team: every teammate's copy of a said message, and silence as a sign of failure."""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm.runtime.program import span_ticks


@primitive(outcomes=["changed"], outputs=["lost"])
def tararc_watch(
    ctx: Context, *, team: list[Any], lost: list[Any], silence: float = 5.0, message: str = "tararc_alive"
) -> Outcome:
    """Listen to the team's heartbeats (`message`, said with data `{lost: [...]}`) until more robots
    are known lost than `lost`: one silent for `silence` seconds, or one a teammate says is lost.

    Lost robots are a set that only grows, so teammates that hear of the same losses agree.
    """
    known = {str(r) for r in lost}
    watched = {str(r) for r in team} - known - {ctx.agent}
    heard = dict.fromkeys(watched, ctx.tick)
    quiet = span_ticks(silence, ctx.dt)
    before = len(known)  # `known` only grows: it changed when it grew

    def news() -> bool:
        while (m := ctx.receive(message)) is not None:
            if m.sender in heard:
                heard[m.sender] = ctx.tick
            said = m.data.get("data", {}).get("lost", [])
            if said:
                known.update(map(str, said))
        due = ctx.tick - quiet
        if heard and min(heard.values()) <= due:  # someone silent: one look at the clock each tick else
            known.update(r for r, tick in heard.items() if tick <= due)
        return len(known) > before

    ctx.wait_until(news)
    return Outcome("changed", lost=sorted(known))


@primitive(outcomes=["silent"], outputs=["heard"])
def partner_silent(
    ctx: Context, *, message: str, partner: str = "", silence: float = 20.0, grace: float = 60.0
) -> Outcome:
    """Listen to a partner's heartbeat (`message`, as `say` sends it, from `partner` only; '': from
    any robot, as under a pair's scope, where only the other robot's can come) until
    it has been silent for `silence` seconds, or was never heard within `grace` seconds (it may
    start later). A failed robot says nothing (docs/REFERENCE.md#agents-that-fail): this is how its
    partner learns of it.
    `heard`: whether the partner was heard at all."""
    quiet, late = span_ticks(silence, ctx.dt), span_ticks(grace, ctx.dt)
    start = ctx.tick
    last: list[int] = []

    def gone() -> bool:
        while (m := ctx.receive(message)) is not None:
            if not partner or m.sender == partner:
                last[:] = [ctx.tick]
        return ctx.tick - last[0] >= quiet if last else ctx.tick - start >= late

    ctx.wait_until(gone)
    return Outcome("silent", heard=bool(last))
