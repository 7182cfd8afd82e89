"""`barrier` (docs/REFERENCE.md#barriers): wait until the named agents reach the barrier of the same name.

The agent's round of the barrier is counted by the team (runtime/team.py), whose notices travel
through the world; it passes when enough members' notices of this round have been heard.
"""

from __future__ import annotations

from typing import Any

from hfsm.builtins.registry import Builtin, Literals
from hfsm.names import did_you_mean
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.runtime.scopes import members as members_in
from hfsm.runtime.scopes import radio_at
from hfsm.runtime.team import Team
from hfsm.spec import BehaviourSpec, ParamSpec


class Barrier:
    """One agent waiting in barrier `name`, round `round`, for `need` of `members` (in run order)."""

    __slots__ = ("agent", "deadline", "entered", "members", "name", "need", "round", "sent", "team")

    def __init__(self, team: Team, agent: str, name: str, members: list[str], need: int, tick: int) -> None:
        self.team = team
        self.agent = agent
        self.name = name
        self.members = members
        self.need = need
        self.round = team.enter(agent, name)
        self.entered = tick
        self.sent = -1
        self.deadline: int | None = None  # advanced in every tick the run processes
        team.waiting.append(self)

    def advance(self, tick: int) -> Event | None:
        team = self.team
        if tick > self.entered:
            arrived = team.arrived(self)
            if len(arrived) >= self.need:
                team.waiting.remove(self)
                return Event("passed", {"arrived": arrived})
        if self.sent != tick:
            self.sent = tick
            for other in self.members:
                team.post(self.agent, other, self.name, self.round, answer=False)
        return None

    def cancel(self) -> str:
        if self in self.team.waiting:
            self.team.waiting.remove(self)
        return ""


def start(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> Barrier | Event:
    name, named, at_least = params["name"], params["agents"], params["at_least"]
    team = host.team
    radio = radio_at(where)
    if not radio.top:  # docs/REFERENCE.md#scopes: the scope's agents, and the name qualified by the scope
        chosen = members_in(radio, agent.name, named)
        if isinstance(chosen, str):
            return Event("error", error=f"barrier '{name}': {chosen}")
        if at_least < 0 or at_least > len(chosen):
            count = len(chosen)
            problem = f"at_least is {at_least}, but it names {count} agent{'s' * (count != 1)}"
            return Event("error", error=f"barrier '{name}': {problem}")
        qualified = radio.qualify(name)
        return Barrier(team, agent.name, qualified, chosen, at_least or len(chosen), host.tick)
    problem = _problem(list(team.order), agent.name, named, at_least)
    if problem:
        return Event("error", error=f"barrier '{name}': {problem}")
    chosen_all = set(named) if named else {a for a in team.order if a != agent.name}
    members = sorted(chosen_all, key=team.order.__getitem__)
    return Barrier(team, agent.name, name, members, at_least or len(members), host.tick)


def _problem(agents: list[str], me: str, named: list[Any], at_least: int) -> str:
    for other in named:
        if not isinstance(other, str) or other not in agents:
            hint = did_you_mean(other, agents) if isinstance(other, str) else ""
            return f"no agent named {other!r}" + (hint or f" (agents: {', '.join(agents)})")
        if other == me:
            return f"names the agent itself ('{me}')"
    if len(set(named)) != len(named):
        return "names an agent twice"
    count = len(named) if named else len(agents) - 1
    if at_least < 0 or at_least > count:
        return f"at_least is {at_least}, but it names {count} agent{'s' * (count != 1)}"
    return ""


def blocks(with_: Literals) -> str | None:
    return "'barrier'"


BARRIER = Builtin(
    BehaviourSpec(
        "barrier",
        "builtin",
        {
            "name": ParamSpec("name", "str", doc="the barrier; agents meet at the same name"),
            "agents": ParamSpec(
                "agents", "list", required=False, default=[], doc="agent ids; empty: every other agent"
            ),
            "at_least": ParamSpec(
                "at_least", "int", required=False, default=0, doc="how many must arrive; 0: all"
            ),
        },
        ("passed",),
        outputs=frozenset({"arrived"}),
        doc="Wait until the named agents reach the barrier of the same name (docs/REFERENCE.md#barriers).",
    ),
    start,
    blocks=blocks,
    role="barrier",
    traced=("arrived",),
)
