"""tararc_exchange: robots share their data over a lossy radio and agree on whose data they hold.

Each robot says the data it holds (its own and every teammate's it has heard, directly or relayed)
and merges what it hears, until every teammate still talking says it holds the same robots. A robot
that fails while the team shares is then in every survivor's set or in none: one that heard its
data relays it to the others, so a lost copy cannot leave it in some robots' plans and not others'.
"""

from __future__ import annotations

from typing import Any

from hfsm.primitive import Context, Outcome, primitive
from hfsm.runtime.program import span_ticks


class Holdings:
    """What one robot holds of the exchange, and what it heard each teammate say it holds."""

    def __init__(self, me: str, data: Any, team: set[str] | None) -> None:
        self.me = me
        self.team = team  # None: open, the team is whoever is heard
        self.held: dict[str, Any] = {me: data}
        self.says: dict[str, frozenset[str]] = {}  # teammate -> the robots it last said it holds
        self.last: dict[str, int] = {}  # teammate -> the tick it was last heard in

    def member(self, robot: str) -> bool:
        return self.team is None or robot in self.team or robot == self.me

    def hear(self, sender: str, held: dict[str, Any], team: list[Any] | None, tick: int) -> bool:
        """Merge a teammate's holdings (and, when this robot could not meet its team, the team the
        teammate met: `team`); whether this robot now holds more."""
        if self.team is None and team is not None:
            self.team = ({str(r) for r in team} | {sender}) - {self.me}
        if sender == self.me or not self.member(sender):
            return False
        self.last[sender] = tick
        theirs = {str(r): d for r, d in held.items() if self.member(str(r))}
        self.says[sender] = frozenset(theirs)
        more = {r: d for r, d in theirs.items() if r not in self.held}
        self.held.update(more)
        return bool(more)

    def silent(self, robot: str, tick: int, start: int, quiet: int | None) -> bool:
        return quiet is not None and tick - self.last.get(robot, start) >= quiet

    def agreed(self, tick: int, start: int, quiet: int | None) -> bool:
        """Every teammate is held or silent (open, until a teammate that met the team names it:
        `quiet` has passed), and every teammate held that still talks last said it holds exactly
        the robots this one holds."""
        if self.team is None:
            if quiet is None or tick - start < quiet:
                return False
        elif any(r not in self.held and not self.silent(r, tick, start, quiet) for r in self.team):
            return False
        mine = frozenset(self.held)
        return all(self.says.get(r) == mine or self.silent(r, tick, start, quiet)
                   for r in self.held if r != self.me)


@primitive(outcomes=["agreed"], outputs=["heard", "team", "held", "talking"])
def tararc_exchange(ctx: Context, *, message: str, data: dict[str, Any], team: list[Any],
                    silence: float = 0.0, every: float = 0.5, open: bool = False) -> Outcome:
    """Say `{held: {robot: data}, team: [robots]}` as `message` (as `say` sends it: `{round,
    data}`) at once, again whenever this robot holds more, and every `every` seconds; merge what
    teammates say; end when every teammate of `team` (but this one) is held and every teammate held
    last said the same set of robots. With `silence` > 0 a teammate not heard for `silence` seconds
    (from the start, if never) is neither waited for nor asked to agree: it failed. `open`: this
    robot could not meet its team; it takes the team a teammate that met it says, or, if none does,
    whoever it hears within `silence` seconds. Copies from robots outside the team, and robots
    outside it that they hold, are read and dropped. Outputs `heard`, the teammates' data by id,
    `team`, their ids, `held`, `heard` with this robot's own, and `talking`, the teammates held
    that are not silent (the ones to wait for at a closing barrier)."""
    hold = Holdings(ctx.agent, data, None if open else {str(r) for r in team} - {ctx.agent})
    start, pause = ctx.tick, max(1, span_ticks(every, ctx.dt))
    quiet = span_ticks(silence, ctx.dt) if silence > 0 else None
    due = start

    def settle() -> bool:
        nonlocal due
        more = False
        while (m := ctx.receive(message)) is not None:
            said = m.data.get("data", {})
            held = said.get("held") if isinstance(said, dict) else None
            if isinstance(held, dict):
                met = said.get("team")
                team_met = met if isinstance(met, list) else None
                more = hold.hear(m.sender, held, team_met, ctx.tick) or more
        if more or ctx.tick >= due:
            said = {"held": dict(sorted(hold.held.items()))}
            if hold.team is not None:
                said["team"] = sorted(hold.team | {ctx.agent})
            ctx.send(message, keep="last", round=0, data=said)  # holdings only grow: the newest says all
            due = ctx.tick + pause
        return hold.agreed(ctx.tick, start, quiet)

    ctx.wait_until(settle)
    heard = {r: d for r, d in sorted(hold.held.items()) if r != ctx.agent}
    talking = [r for r in heard if not hold.silent(r, ctx.tick, start, quiet)]
    return Outcome("agreed", heard=heard, team=sorted(heard), held=dict(sorted(hold.held.items())),
                   talking=talking)
