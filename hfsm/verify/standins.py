"""Stand-ins: a primitive (or a machine named with --stand-in) replaced by a behaviour that may end
with any of its declared outcomes, after any of the few durations that matter.

Durations that matter are those that order its end against a timer: at once (the next tick: a
stand-in that ended in the tick it began would let a loop of stand-ins spin without time passing,
which no robot's action does), and one tick before, at, and one tick after each timer of any agent
that is due later (beyond the first timer above the call itself, which cancels it, nothing more can
be told apart).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from hfsm.primitive import Primitive
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec
from hfsm.verify.choices import Counter, Decider
from hfsm.verify.values import ANY


class StandInActivity:
    __slots__ = ("deadline", "outcome", "outputs")

    def __init__(self, outcome: str, outputs: dict[str, Any], deadline: int) -> None:
        self.outcome = outcome
        self.outputs = outputs
        self.deadline: int | None = deadline

    def advance(self, tick: int) -> Event | None:
        if self.deadline is not None and tick >= self.deadline:
            return Event(self.outcome, dict(self.outputs))
        return None

    def cancel(self) -> str:
        return ""


def _unused(ctx: Any, **params: Any) -> str:
    raise RuntimeError("a stand-in runs as an activity, never as a function")


@dataclasses.dataclass(frozen=True)
class StandIn(Primitive):
    """A primitive the engine starts with `start_activity` (hfsm.runtime.calls) instead of its code."""

    decider: Decider | None = None
    outputs: Mapping[str, Any] = dataclasses.field(default_factory=dict)
    variants: Mapping[str, Sequence[Mapping[str, Any]]] = dataclasses.field(default_factory=dict)  # by agent

    def start_activity(
        self, host: Host, agent: Agent, params: dict[str, Any], where: Frame | Region
    ) -> StandInActivity:
        assert self.decider is not None
        now = host.tick
        names = sorted(self.spec.outputs or ())
        outputs = {name: self.outputs.get(name, 0) for name in names}
        given = self.variants.get(agent.name, self.variants.get(ANY, ()))
        sets = [{**outputs, **{n: v[n] for n in names if n in v}} for v in given] or [outputs]
        outcomes = sorted(self.spec.outcomes)
        options = [
            {"outcome": outcome, "after": after, **({"outputs": one} if len(sets) > 1 else {})}
            for after in durations(host, agent, where)
            for outcome in outcomes
            for one in sets
        ]
        counter: Counter = host.world  # type: ignore[attr-defined]  # the engine's, which has one
        what = f"{self.spec.name} of {agent.name} at {'/'.join(where.path())}"
        chosen = self.decider.pick(counter, now, "stand_in", what, options)
        ended = chosen.get("outputs", sets[0])
        return StandInActivity(str(chosen["outcome"]), dict(ended), now + int(chosen["after"]))


def stand_in(
    spec: BehaviourSpec,
    decider: Decider,
    outputs: Mapping[str, Any],
    variants: Mapping[str, Sequence[Mapping[str, Any]]] | None = None,
) -> StandIn:
    """`variants`: by agent (ANY: the others), the sets of outputs a call may end with (a choice
    when more than one); each over `outputs`."""
    spec = dataclasses.replace(spec, kind="primitive", world=None)
    return StandIn(spec, _unused, decider, dict(outputs), dict(variants or {}))


def durations(host: Host, agent: Agent, where: Frame | Region) -> list[int]:
    """Ticks after which a stand-in started now may end, fewest first."""
    now = host.tick
    own = [d for d in _own_timers(where) if d > now]
    cap = min(own) if own else None
    ticks = {1}
    for agents in getattr(host, "agents", ()):
        if agents.root is None or agents.result is not None:
            continue
        for deadline in _timers(agents.root):
            for tick in (deadline - 1, deadline, deadline + 1):
                if tick > now and (cap is None or tick <= cap):
                    ticks.add(tick - now)
    if cap is not None:
        ticks.add(cap - now)
    return sorted(ticks)


def _own_timers(where: Frame | Region) -> Iterator[int]:
    """The timers of the machines and states above a call: the first to fire cancels it."""
    up: Any = where
    while up is not None:
        frame = up.owner if isinstance(up, Region) else up
        for deadline in (frame.deadline, frame.state_deadline, frame.retry_at):
            if deadline is not None:
                yield deadline
        up = frame.up


def _timers(frame: Frame) -> Iterator[int]:
    for deadline in (frame.deadline, frame.state_deadline, frame.retry_at):
        if deadline is not None:
            yield deadline
    below = frame.below
    if below.__class__ is Frame:
        yield from _timers(below)
    elif below.__class__ is list:
        for region in below:
            inner = region.below
            if inner.__class__ is Frame:
                yield from _timers(inner)
            elif inner is not None and inner.deadline is not None:
                yield inner.deadline
    elif below is not None and below.deadline is not None:
        yield below.deadline
