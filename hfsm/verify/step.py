"""One tick of a run under the search, as `hfsm.runtime.run` runs it in world `none`: the failures
chosen for the tick, then what arrives, then each agent's turn."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from itertools import combinations
from typing import Any

from hfsm.runtime.agent import Agent, frames
from hfsm.runtime.engine import Engine, FatalError
from hfsm.runtime.failing import FAIL_REASON, fail
from hfsm.runtime.program import Program
from hfsm.runtime.run import RunOptions, _next_tick, _start, _wake
from hfsm.runtime.scopes import run_under
from hfsm.verify.choices import Chooser, Decider
from hfsm.verify.radio import ChoosingWorld


class _NoFailures:
    def __init__(self) -> None:
        self.due: list[tuple[int, str, str]] = []


NO_FAILURES: Any = _NoFailures()
DEFER_FAILURES = True  # put off failing an agent whose turn changes nothing (False: a test's baseline)


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
    before, wake = engine.tick, engine.clock.wake
    following = _next_tick(engine, NO_FAILURES, None)
    if following is None:
        return Ended("blocked", "blocked forever")
    if following > last:
        return Ended("bound", "still running at the bound")
    engine.tick = world.tick = following
    if world.fail_left > 0:
        some = None if wake or not DEFER_FAILURES else acting(engine, world, before, following)
        _fail_some(engine, world, decider, some)
    arrived = world.collect(following)
    running = engine.running
    try:
        if arrived:
            engine.deliver(arrived)
        for agent in engine.agents:
            if agent.result is None:
                agent.entries = 0
                engine.step(agent.root)  # type: ignore[arg-type]
    except FatalError as exc:
        return Ended("error", exc.args[0], exc.agent)
    if engine.running < running and isinstance(decider, Chooser):
        decider.restore = True  # an agent ended: a failure deferred in this tick may not come later
    _forget(engine)
    return None


def successors(
    chooser: Chooser, engine_for: Callable[[], Engine], last: int
) -> Iterator[tuple[Engine, Ended | None]]:
    """Every run of one state's next tick, once for each combination of its choices, in the order
    the search takes them; `engine_for()` gives the state afresh for each run. The failures the tick
    put off are run too when one of its runs ended an agent (`Chooser.restore`, docs/VERIFY.md,
    *Failures that change nothing*). A consumer may stop early (at a violation)."""
    pending: list[tuple[int, ...]] = [()]
    chooser.held, chooser.restore = [], False
    while pending:
        chooser.begin(pending.pop())
        engine = engine_for()
        ended = next_state(engine, engine.world, chooser, last)  # type: ignore[arg-type]
        pending.extend(chooser.siblings())
        yield engine, ended
        if not pending and chooser.restore and chooser.held:
            pending, chooser.held = chooser.held, []


def top_outcomes(engine: Engine) -> Iterator[str]:
    """The outcomes of the top machine its agents ended in (not by failing)."""
    for agent in engine.agents:
        if agent.result is not None and agent.result.failed is None and agent.result.outcome:
            yield agent.result.outcome


def acting(engine: Engine, world: ChoosingWorld, before: int, tick: int) -> set[str]:
    """The running agents whose turn in `tick` (the one after `before`) may do anything: something
    of theirs is due, something arrives for them, or they wait in a barrier. The others' turns
    change nothing (the engine skips ticks in which no agent has anything due), so failing one of
    them now is failing it at its next tick that does (docs/VERIFY.md, *Failures that change
    nothing*)."""
    found = {w.agent for w in engine.team.waiting}
    found.update(m.to for arrives, _, m in world.flying if arrives <= tick)
    for agent in engine.agents:
        root = agent.root
        if agent.result is None and root is not None and _wake(root, before, sys.maxsize) <= tick:
            found.add(agent.name)
    return found


def _fail_some(
    engine: Engine, world: ChoosingWorld, decider: Decider, acting: set[str] | None = None
) -> None:
    """Choose which running agents fail now (at least one keeps running); failing one that is not
    `acting` (None: all are) is a deferred option."""
    if world.fail_left <= 0:
        return
    running = [a.name for a in engine.agents if a.result is None]
    subsets: list[Sequence[str]] = [()]
    for size in range(1, min(world.fail_left, len(running) - 1) + 1):
        subsets.extend(combinations(running, size))
    if len(subsets) == 1:
        return
    options = [{"agents": list(s)} for s in subsets]
    deferred = () if acting is None else [i for i, s in enumerate(subsets) if not acting.issuperset(s)]
    chosen = decider.pick(_Uncounted(), engine.tick, "fail", "agents that fail now", options, deferred)
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
        if agent.result is None and agent.root is not None:
            for frame in frames(agent.root):
                frame._scope = frame._prefix = None  # made again when asked (a tenth of a copy's bytes)


def discard(engine: Engine) -> None:
    """Break the links that make an engine no longer used a cycle (its parts wired to each other,
    frames to their agent and caller, barriers to the team), so that freeing it is the reference
    counts' work, not the collector's: the collector's young collections scan every object made
    and were a fifth of a long search. The engine is unusable after."""
    for agent in engine.agents:
        if agent.root is not None:
            for frame in list(frames(agent.root)):  # all first: unlinking one hides what runs below it
                below = frame.below
                if below.__class__ is list:
                    for region in below:
                        region.owner = region.below = None
                frame.agent = frame.up = frame.below = frame._scope = None  # type: ignore[assignment]
        agent.__dict__.clear()
    loop = engine.loop
    parts = [loop, loop.calls, loop.arcs, loop.regions, loop.timers, engine.mailbox, engine.holds]
    for part in [*parts, engine.ledger, engine.cancelling, engine.team, engine]:
        part.__dict__.clear()


def running(agents: Sequence[Agent]) -> list[Agent]:
    return [a for a in agents if a.result is None]
