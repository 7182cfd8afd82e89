"""The pure steps of TARARC's state exchange, which machines/tararc_exchange.yaml loops over: the
radio (tell, listen) is the machine's; what a robot holds, merging a teammate's copy and deciding
"everyone heard everyone" are these (`hfsm_behaviours.tararc.holdings`), with no radio inside."""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm.runtime.program import span_ticks
from hfsm_behaviours.tararc import holdings

NEVER = 1e6  # seconds: `wake` when only a message can change the decision


@primitive(outcomes=["held"], outputs=["hold", "said"])
def tararc_hold(ctx: Context, *, data: dict[str, Any], team: list[Any], silence: float = 0.0,
                open: bool = False) -> Outcome:
    """What this robot holds as the exchange starts: its own `data`, the `team` (but this robot) to
    agree with (`open`: not known yet, the team a teammate that met it says, or whoever is heard
    within `silence` s), a teammate silent for `silence` s (> 0) failed. `said`: what it says."""
    quiet = span_ticks(silence, ctx.dt) if silence > 0 else None
    hold = holdings.holding(ctx.agent, data, None if open else team, ctx.tick, quiet)
    return Outcome("held", hold=hold, said=holdings.said(hold))


@primitive(outcomes=["more", "same"], outputs=["hold", "said"])
def tararc_merge(ctx: Context, *, hold: dict[str, Any], sender: str, said: dict[str, Any]) -> Outcome:
    """A teammate's copy (`said`, from `sender`: `{held: {robot: data}, team: [robots]}`) merged
    into `hold`: `more` when this robot now holds more robots' data. Copies from robots outside the
    team, and robots outside it that they hold, are read and dropped."""
    new, more = holdings.merge(hold, sender, said, ctx.tick)
    return Outcome("more" if more else "same", hold=new, said=holdings.said(new))


@primitive(outcomes=["agreed", "waiting"], outputs=["wake", "heard", "team", "held", "talking"])
def tararc_agreed(ctx: Context, *, hold: dict[str, Any]) -> Outcome:
    """Everyone heard everyone: every teammate is held or silent, and every teammate held that still
    talks last said it holds the robots this one holds. `wake`: seconds until a silence alone could
    change that (1e6: never). Outputs `heard` (the teammates' data by id), `team` (their ids), `held`
    (with this robot's own) and `talking` (the teammates held that are not silent)."""
    ticks = holdings.wake(hold, ctx.tick)
    out = holdings.results(hold, ctx.tick)
    return Outcome("agreed" if holdings.agreed(hold, ctx.tick) else "waiting",
                   wake=NEVER if ticks is None else round(ticks * ctx.dt, 9), **out)
