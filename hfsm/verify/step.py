"""One tick of a run under the search, as `hfsm.runtime.run` runs it in world `none`: the failures
chosen for the tick, then what arrives, then each agent's turn."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from itertools import combinations
from typing import Any

from hfsm.runtime.agent import Agent
from hfsm.runtime.engine import Engine, FatalError
from hfsm.runtime.failing import FAIL_REASON, fail
from hfsm.runtime.program import Program
from hfsm.runtime.run import RunOptions, _next_tick, _start
from hfsm.runtime.scopes import run_under
from hfsm.verify.choices import Decider
from hfsm.verify.radio import ChoosingWorld


class _NoFailures:
    def __init__(self) -> None:
        self.due: list[tuple[int, str, str]] = []


NO_FAILURES: Any = _NoFailures()


@dataclass
class Ended:
    """How a tick ended the search of a run: why ("blocked", "bound", "error"), and the text."""

    why: str
    text: str
    agent: str = ""


def first_state(
    program: Program, options: RunOptions, decider: Decider, world: ChoosingWorld
) -> Engine | Ended:
    """Tick 0: the failures chosen at 0 s, then every agent that did not fail starts."""
    agents = [Agent(n, options.top, None, options.seed, world) for n in options.agents]
    world.start([a.name for a in agents], program.dt)
    engine = Engine(agents, world, program.dt, None)
    if options.scopes:
        run_under(agents, options.scopes)
    _fail_some(engine, world, decider)
    try:
        _start(engine, program.machines[options.top], options)
    except FatalError as exc:
        return Ended("error", exc.args[0], exc.agent)
    _forget(engine)
    return engine


def next_state(engine: Engine, world: ChoosingWorld, decider: Decider, last: int) -> Ended | None:
    """Run the next tick in which something can happen; why the run cannot go on, or None."""
    following = _next_tick(engine, NO_FAILURES, None)
    if following is None:
        return Ended("blocked", "blocked forever")
    if following > last:
        return Ended("bound", "still running at the bound")
    engine.tick = world.tick = following
    _fail_some(engine, world, decider)
    arrived = world.collect(following)
    try:
        if arrived:
            engine.deliver(arrived)
        for agent in engine.agents:
            if agent.result is None:
                agent.entries = 0
                engine.step(agent.root)  # type: ignore[arg-type]
    except FatalError as exc:
        return Ended("error", exc.args[0], exc.agent)
    _forget(engine)
    return None


def _fail_some(engine: Engine, world: ChoosingWorld, decider: Decider) -> None:
    if world.fail_left <= 0:
        return
    running = [a.name for a in engine.agents if a.result is None]
    subsets: list[Sequence[str]] = [()]
    for size in range(1, min(world.fail_left, len(running) - 1) + 1):
        subsets.extend(combinations(running, size))
    if len(subsets) == 1:
        return
    options = [{"agents": list(s)} for s in subsets]
    chosen = decider.pick(_Uncounted(), engine.tick, "fail", "agents that fail now", options)
    for name in chosen["agents"]:
        world.fail_left -= 1
        fail(engine, engine.by_name[name], FAIL_REASON)


class _Uncounted:
    """Failures are no numbered choice point: a replay gets them as `--fail` does."""

    n = 0


def _forget(engine: Engine) -> None:
    """What does not change what can happen next: statistics and caches (none copied with a state)."""
    engine.spans.clear()
    for agent in engine.agents:
        agent.stats.clear()
        inputs = agent.inputs
        inputs._declared = None  # read again from the world when asked
        inputs._tick = -1


def running(agents: Sequence[Agent]) -> list[Agent]:
    return [a for a in agents if a.result is None]
