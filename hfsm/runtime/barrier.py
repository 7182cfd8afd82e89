"""The `barrier` built-in (docs/REFERENCE.md#barriers): rounds per name, notices sent through the world,
answers.

A notice (N, r) says "I am at barrier N, round r". Notices travel through the world like messages
(its latency, its loss) but are the engine's own: they never enter a mailbox or the trace.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any, Protocol

from hfsm.names import did_you_mean
from hfsm.primitive import Message
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.scopes import members as members_in
from hfsm.runtime.scopes import radio_at
from hfsm.world import NOTICE

if TYPE_CHECKING:
    from hfsm.runtime.core import Core
    from hfsm.runtime.host import Host


class Team:
    """What every agent knows of barriers: its own rounds, the highest round heard per name and sender."""

    def __init__(self, engine: Core) -> None:
        self.engine = engine
        # A world may script team mates that are no agents of the run (a behaviour test's partners):
        # members of barriers after the agents, whose notices the world sends.
        partners = getattr(engine.world, "partners", None)
        self.partners: Partners | None = partners
        names = [a.name for a in engine.agents] + (list(partners.names()) if partners else [])
        self.order = {name: i for i, name in enumerate(names)}
        self.rounds: dict[str, dict[str, int]] = {name: {} for name in names}
        self.heard: dict[str, dict[tuple[str, str], int]] = {name: {} for name in names}
        self.waiting: list[Barrier] = []
        # Notices in flight that raise what their receiver holds: (to, name, sender, round).
        self.fresh: set[tuple[str, str, str, int]] = set()

    def enter(self, agent: str, name: str) -> int:
        rounds = self.rounds[agent]
        rounds[name] = rounds.get(name, 0) + 1
        return rounds[name]

    def is_waiting(self, agent: str, name: str) -> bool:
        return any(b.agent == agent and b.name == name for b in self.waiting)

    def post(self, sender: str, to: str, name: str, round_: int, *, answer: bool) -> None:
        if self.heard[to].get((name, sender), 0) < round_:
            self.fresh.add((to, name, sender, round_))
        data = {"barrier": name, "round": round_, "answer": answer}
        self.engine.world.post(Message(NOTICE, sender, to, data, self.engine.tick))

    def receive(self, message: Message) -> None:
        """A notice enters its receiver (who has not failed) at the start of a tick; answer it if due."""
        to, sender = message.to, message.sender
        name, round_ = message.data["barrier"], message.data["round"]
        self.fresh.discard((to, name, sender, round_))
        heard = self.heard[to]
        if heard.get((name, sender), 0) < round_:
            heard[name, sender] = round_
        own = self.rounds[to].get(name, 0)
        if not message.data["answer"] and own >= round_ and not self.is_waiting(to, name):
            self.post(to, sender, name, own, answer=True)

    def arrived(self, barrier: Barrier) -> list[str]:
        heard = self.heard[barrier.agent]
        return [a for a in barrier.members if heard.get((barrier.name, a), 0) >= barrier.round]

    def live(self) -> bool:
        """Whether a waiting barrier can still pass: for 'blocked forever' (docs/REFERENCE.md#hfsm-run,
        docs/REFERENCE.md#barriers).

        It can while it holds enough notices, or while a notice it lacks can still come: one in
        flight, one a partner sends while waiting in it, or a partner's answer to its next notice.
        """
        for b in self.waiting:
            held = self.arrived(b)
            if len(held) >= b.need:
                return True
            for other in b.members:
                if other not in held and self._can_come(b, other):
                    return True
        return False

    def _can_come(self, b: Barrier, other: str) -> bool:
        agent = self.engine.by_name.get(other)
        if agent is None:  # a scripted partner: its notice comes if it arrives at this round
            return self.partners is not None and self.partners.round_of(other, b.name) >= b.round
        if agent.failed is not None:
            return False
        for to, name, sender, round_ in self.fresh:
            if to == b.agent and name == b.name and sender == other and round_ >= b.round:
                return True
        if self.rounds[other].get(b.name, 0) < b.round:
            return False
        theirs = [w for w in self.waiting if w.agent == other and w.name == b.name]
        return not theirs or any(b.agent in w.members for w in theirs)


class Partners(Protocol):
    """Team mates a world scripts (a behaviour test's): they take part in barriers, nothing else."""

    def names(self) -> Sequence[str]: ...

    def round_of(self, partner: str, name: str) -> int:
        """The last round of barrier `name` this partner reaches in the run."""


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


def start_barrier(
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
