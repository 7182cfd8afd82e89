"""What a run must never do, looked at after every tick: hang, error, a failure outcome with
`--goal success`, and the user's properties (`hfsm.verify.props`)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from hfsm.builtins.barrier import Barrier
from hfsm.builtins.wait import Wait
from hfsm.builtins.wait_for import WaitFor
from hfsm.runtime.agent import Agent, Frame, Region, frames, leaves
from hfsm.runtime.engine import Engine
from hfsm.runtime.run import _next_tick
from hfsm.verify.props import Props
from hfsm.verify.standins import StandInActivity
from hfsm.verify.step import NO_FAILURES, Ended

Found = tuple[str, str, str]  # kind, agent(s), text


class Properties:
    def __init__(self, failures: frozenset[str], goal: bool, props: Props | None, bound: float) -> None:
        self.failures = failures
        self.goal = goal
        self.props = props or Props()
        self.bound = bound

    def __call__(self, engine: Engine, ended: Ended | None) -> Found | None:
        if ended is not None:
            return self._ended(engine, ended)
        if self.goal:
            for agent in engine.agents:
                result = agent.result
                if result is not None and result.failed is None and result.outcome in self.failures:
                    text = (
                        f"{agent.name} ended in '{result.outcome}', a failure of its top machine, "
                        f"at t={result.time:g} s"
                    )
                    return "failure_outcome", agent.name, text
        props = self.props
        if props.never_together or props.left_within:
            found = self._states(engine)
            if found is not None:
                return found
        if props.at_end and engine.running == 0:
            return self._at_end(engine)
        return None

    def _ended(self, engine: Engine, ended: Ended) -> Found:
        if ended.why == "error":
            return "error", ended.agent, ended.text
        stuck = [a for a in engine.agents if a.result is None and a.root is not None]
        how = (
            "blocked forever" if ended.why == "blocked" else f"still running at the bound ({self.bound:g} s)"
        )
        text = f"{how} at t={engine.time:g} s: " + "; ".join(f"{a.name} in {waits(a)}" for a in stuck)
        return "hang", ",".join(a.name for a in stuck), text

    def _states(self, engine: Engine) -> Found | None:
        dt = engine.dt
        for path in self.props.never_together:
            inside = [
                a.name for a in engine.agents if a.result is None and any(_in(f, path) for f in _frames(a))
            ]
            if len(inside) > 1:
                text = (
                    f"{' and '.join(inside)} are in state '{'/'.join(path)}' at once, at t={engine.time:g} s"
                )
                return "property", ",".join(inside), text
        upcoming = _upcoming(engine) if self.props.left_within else None
        for path, seconds in self.props.left_within:
            limit = engine.span(seconds)
            for agent in engine.agents:
                if agent.result is not None:
                    continue
                for frame in _frames(agent):
                    # nothing happens before the next tick: an agent in P stays in it until then
                    if _in(frame, path) and upcoming is not None and upcoming - frame.entered > limit:
                        since = round(frame.entered * dt, 9)
                        late = round((frame.entered + limit + 1) * dt, 9)
                        text = (
                            f"{agent.name} entered '{'/'.join(path)}' at t={since:g} s and is still in "
                            f"it at t={late:g} s (limit {seconds:g} s)"
                        )
                        return "property", agent.name, text
        return None

    def _at_end(self, engine: Engine) -> Found | None:
        results = {a.name: a.result for a in engine.agents}
        names: dict[str, Any] = {
            "agents": list(results),
            "outputs": {n: dict(r.outputs) for n, r in results.items() if r is not None and r.failed is None},
            "outcomes": {n: r.outcome for n, r in results.items() if r is not None and r.failed is None},
            "failed": [n for n, r in results.items() if r is not None and r.failed is not None],
        }
        holds = self.props.holds_at_end(names)
        if holds is True:
            return None
        why = "does not hold" if holds is False else f"raised {holds}"
        return (
            "property",
            ",".join(names["outputs"]),
            f"at the end (t={engine.time:g} s), '{self.props.at_end}' {why}: outputs {names['outputs']}",
        )


def _upcoming(engine: Engine) -> int | None:
    """The next tick in which something happens (the engine's `wake` left as it was)."""
    wake = engine.wake
    try:
        return _next_tick(engine, NO_FAILURES, None)
    finally:
        engine.wake = wake


def _frames(agent: Agent) -> Iterator[Frame]:
    return frames(agent.root) if agent.root is not None else iter(())


def _in(frame: Frame, path: tuple[str, ...]) -> bool:
    full = frame.path()
    return tuple(full[-len(path) :]) == path


def waits(agent: Agent) -> str:
    """Each innermost running state's path and what it waits for."""
    assert agent.root is not None
    return ", ".join(f"{'/'.join(leaf.path())} ({_waits_for(leaf)})" for leaf in leaves(agent.root))


def _waits_for(leaf: Frame | Region) -> str:
    below = leaf.below
    if isinstance(below, Barrier):
        heard = below.team.arrived(below)
        who = ", ".join(heard) or "none"
        return f"barrier '{below.name}' round {below.round}, has {len(heard)} of {below.need} ({who})"
    if isinstance(below, WaitFor):
        return f"waits for message '{below.name}'"
    if isinstance(below, Wait):
        return "waits without end" if below.deadline is None else f"waits until tick {below.deadline}"
    if isinstance(below, StandInActivity):
        return f"stand-in ends '{below.outcome}' at tick {below.deadline}"
    if isinstance(leaf, Frame) and leaf.retry_at is not None:
        return "waits to retry"
    return "waits"
