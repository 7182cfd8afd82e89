"""What the team knows of barriers (docs/REFERENCE.md#barriers): rounds per name, notices sent through
the world, answers. The `barrier` built-in (hfsm/builtins/barrier.py) waits on it.

A notice (N, r) says "I am at barrier N, round r". Notices travel through the world like messages
(its latency, its loss) but are the engine's own: they never enter a mailbox or the trace.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from hfsm.primitive import Message
from hfsm.runtime.agent import Agent
from hfsm.world import NOTICE, World


class Ticking(Protocol):
    tick: int


class Waiting(Protocol):
    """One agent waiting in a barrier (hfsm/builtins/barrier.py): in `round` of `name`, for `need` of
    `members`."""

    agent: str
    name: str
    members: list[str]
    need: int
    round: int


class Team:
    """What every agent knows of barriers: its own rounds, the highest round heard per name and sender."""

    def __init__(self, agents: list[Agent], world: World, clock: Ticking) -> None:
        self.world = world
        self.clock = clock
        self.by_name = {a.name: a for a in agents}
        # A world may script team mates that are no agents of the run (a behaviour test's partners):
        # members of barriers after the agents, whose notices the world sends.
        partners = getattr(world, "partners", None)
        self.partners: Partners | None = partners
        names = [a.name for a in agents] + (list(partners.names()) if partners else [])
        self.order = {name: i for i, name in enumerate(names)}
        self.rounds: dict[str, dict[str, int]] = {name: {} for name in names}
        self.heard: dict[str, dict[tuple[str, str], int]] = {name: {} for name in names}
        self.waiting: list[Waiting] = []
        # Notices in flight that raise what their receiver holds: (to, name, sender, round), kept
        # sorted (not a set, whose order follows the string hashes of the process and its history):
        # equal states are copied to equal bytes, and a copy's bytes survive a load.
        self.fresh: dict[tuple[str, str, str, int], None] = {}

    def enter(self, agent: str, name: str) -> int:
        rounds = self.rounds[agent]
        rounds[name] = rounds.get(name, 0) + 1
        return rounds[name]

    def is_waiting(self, agent: str, name: str) -> bool:
        return any(b.agent == agent and b.name == name for b in self.waiting)

    def post(self, sender: str, to: str, name: str, round_: int, *, answer: bool) -> None:
        if self.heard[to].get((name, sender), 0) < round_:
            notice = (to, name, sender, round_)
            if notice not in self.fresh:
                self.fresh = dict.fromkeys(sorted([*self.fresh, notice]))
        data = {"barrier": name, "round": round_, "answer": answer}
        self.world.post(Message(NOTICE, sender, to, data, self.clock.tick))

    def receive(self, message: Message) -> None:
        """A notice enters its receiver (who has not failed) at the start of a tick; answer it if due."""
        to, sender = message.to, message.sender
        name, round_ = message.data["barrier"], message.data["round"]
        self.fresh.pop((to, name, sender, round_), None)
        heard = self.heard[to]
        if heard.get((name, sender), 0) < round_:
            heard[name, sender] = round_
        own = self.rounds[to].get(name, 0)
        if not message.data["answer"] and own >= round_ and not self.is_waiting(to, name):
            self.post(to, sender, name, own, answer=True)

    def arrived(self, barrier: Waiting) -> list[str]:
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

    def _can_come(self, b: Waiting, other: str) -> bool:
        agent = self.by_name.get(other)
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
