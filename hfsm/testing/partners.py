"""Scripted barrier partners of a behaviour test (docs/REFERENCE.md#barriers): team mates that are no agents
of the run.

A partner that arrives at barrier N at time S sends its notice (N, its round) to every agent of the
test in every tick from then on. In a lossless world this is what an agent that waits there and
then answers amounts to for the agents: they hold its notice from the tick after S on, and a
later round of N is for its next arrival.
"""

from __future__ import annotations

from collections.abc import Sequence

from hfsm.primitive import Message
from hfsm.runtime.program import span_ticks
from hfsm.testing.model import PartnerAt
from hfsm.world import NOTICE


class ScriptedPartners:
    def __init__(self, partners: Sequence[PartnerAt], agents: Sequence[str], dt: float) -> None:
        self._agents = list(agents)
        self._names = list(dict.fromkeys(p.agent for p in partners))
        # (tick of arrival, partner, barrier, round), in time order; rounds count arrivals per name
        counts: dict[tuple[str, str], int] = {}
        self._arrivals: list[tuple[int, str, str, int]] = []
        for p in sorted(partners, key=lambda p: p.at):
            if p.barrier is None:
                continue  # a team mate a scope or a barrier may name, that never arrives anywhere
            counts[p.agent, p.barrier] = counts.get((p.agent, p.barrier), 0) + 1
            self._arrivals.append((span_ticks(p.at, dt), p.agent, p.barrier, counts[p.agent, p.barrier]))
        self._last = counts

    def names(self) -> Sequence[str]:
        return self._names

    def round_of(self, partner: str, name: str) -> int:
        return self._last.get((partner, name), 0)

    def notices(self, tick: int) -> list[Message]:
        """The notices that enter the agents at the start of `tick`: sent in the tick before it."""
        held: dict[tuple[str, str], int] = {}
        for arrived, partner, name, round_ in self._arrivals:
            if arrived >= tick:
                break
            held[partner, name] = round_
        return [
            Message(NOTICE, partner, to, {"barrier": name, "round": round_, "answer": False}, tick - 1)
            for (partner, name), round_ in held.items()
            for to in self._agents
        ]
