"""Breadth-first search over the runs the world's choices allow, each situation explored once.

A state is the engine between two ticks, as bytes (`Snapshots`); its successors are the next tick
run once for every combination of the choices made in it (`Chooser` enumerates them). Breadth first,
so the first violation found is one of the shortest (fewest ticks in which something happened).
"""

from __future__ import annotations

import gc
import math
import random
import time
from collections import deque
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from hfsm.runtime.engine import Engine
from hfsm.runtime.program import Program
from hfsm.runtime.run import RunOptions
from hfsm.verify import parallel
from hfsm.verify.canon import Keys
from hfsm.verify.choices import Choice, Chooser
from hfsm.verify.parallel import Run
from hfsm.verify.radio import ChoosingWorld, Given
from hfsm.verify.snapshot import Snapshots, digest, shared_numbers, shared_objects
from hfsm.verify.step import Ended, discard, first_state, successors, top_outcomes

# A property looked at after each tick: a violation as (kind, agent, text), or None.
Check = Callable[[Engine, "Ended | None"], "tuple[str, str, str] | None"]


_RNG = random.Random(0)
GC_YOUNG = 100_000  # allocations between two young collections while searching (CPython's: 700)
LIVE = 20_000  # states queued as engines too: the first successor runs on it, not on a copy


@dataclass
class Budget:
    loss: int = 0
    delay: int = 0
    fail: int = 0
    last_tick: int = 12000
    max_states: int = 1_000_000
    max_seconds: float = math.inf


@dataclass
class Violation:
    kind: str
    agent: str
    text: str
    tick: int
    choices: list[Choice]


@dataclass
class Outcome:
    states: int = 0
    exhausted: bool = False
    seconds: float = 0.0
    violation: Violation | None = None
    top_outcomes: set[str] = field(default_factory=set)  # reached by some agent in some run


@dataclass
class _Node:
    parent: int
    choices: list[Choice]


def explore(
    program: Program,
    options: RunOptions,
    budget: Budget,
    check: Check,
    chooser: Chooser,
    inputs: dict[str, Any],
    unobserved: frozenset[str] | None = None,
    workers: int = 1,
) -> Outcome:
    """Search from tick 0; `program`'s stand-ins must ask `chooser`. A state's key is the hash of
    its copy's bytes, or with `unobserved` (a frame's times that nothing reads, `build.unobserved`)
    written by value (`canon.Keys`, docs/VERIFY.md). With `workers` > 1, the ticks are run by that
    many processes (`parallel`)."""
    given = Given(inputs)
    search = Search(program, budget, check, chooser, given, unobserved)
    threshold = gc.get_threshold()
    gc.collect()
    gc.freeze()  # the program and everything loaded before: never scanned again while states churn
    gc.set_threshold(GC_YOUNG, *threshold[1:])
    try:
        first = lambda: _first(program, options, chooser, budget, given)  # noqa: E731
        if workers > 1:
            return parallel.run(search, workers, first)
        return search.run(first)
    finally:
        gc.set_threshold(*threshold)
        gc.unfreeze()
        search.snaps.close()


class Search:
    def __init__(
        self,
        program: Program,
        budget: Budget,
        check: Check,
        chooser: Chooser,
        given: Given,
        unobserved: frozenset[str] | None = None,
    ) -> None:
        self.started = time.perf_counter()
        self.budget = budget
        self.check = check
        self.chooser = chooser
        shared = shared_objects([program, chooser, program.registry, _RNG, given])
        self.snaps = Snapshots(shared)
        self.key = None if unobserved is None else Keys(shared_numbers(shared), unobserved=unobserved)
        self.live_cap = LIVE
        self.result = Outcome()
        self.nodes: list[_Node] = []
        self.seen: dict[bytes, int] = {}  # a state's key: the latest tick it was explored at
        self.explored = 0  # states queued (a key again at a later tick is explored again)
        self.ends = 0  # runs that ended (each a state of its own, never hashed)
        self.queue: deque[tuple[int, bytes, Engine | None]] = deque()
        self.live = 0  # engines in the queue

    def run(self, first: Callable[[], tuple[Engine, Ended | None]]) -> Outcome:
        for engine, ended in self.roots(first):
            if not self.visit(engine, ended, -1):
                return self.done(False)
        chooser, snaps, last = self.chooser, self.snaps, self.budget.last_tick
        while self.queue:
            if self.over():
                return self.done(False)
            index, data, live = self.queue.popleft()
            if live is not None:
                self.live -= 1
            for engine, ended in successors(chooser, _first_itself(live, snaps, data), last):
                if not self.visit(engine, ended, index):
                    return self.done(False)
        return self.done(True)

    @property
    def last_tick(self) -> int:
        return self.budget.last_tick

    @property
    def top_outcomes(self) -> set[str]:
        return self.result.top_outcomes

    def roots(self, first: Callable[[], Run]) -> Iterator[Run]:
        """Tick 0, once for every choice made in it."""
        return _all_prefixes(self.chooser, first)

    def over(self) -> bool:
        """Whether the budget of states or of seconds is spent."""
        if self.explored >= self.budget.max_states:
            return True
        return time.perf_counter() - self.started > self.budget.max_seconds

    def visit(self, engine: Engine, ended: Ended | None, parent: int) -> bool:
        """Record a state reached; False when it violates a property (result.violation set). An
        engine not queued is discarded (`step.discard`)."""
        made = list(self.chooser.made)
        self.result.top_outcomes.update(top_outcomes(engine))
        found = self.check(engine, ended)
        if found is not None:
            return self.violated(found, engine.tick, parent, made)
        if ended is not None or engine.running == 0:
            self.ends += 1
            discard(engine)
            return True
        if self.key is None:
            data = self.snaps.dump(engine)
            key = digest(data)
        else:
            key = self.key(engine)
        if not self.fresh(key, engine.tick):
            discard(engine)
            return True
        if self.key is not None:
            data = self.snaps.dump(engine)
        index = self.queued(parent, made)
        if self.live < self.live_cap:
            self.live += 1
            self.queue.append((index, data, engine))
        else:
            self.queue.append((index, data, None))
            discard(engine)
        return True


    def violated(self, found: tuple[str, str, str], tick: int, parent: int, made: list[Choice]) -> bool:
        self.nodes.append(_Node(parent, made))
        self.result.violation = Violation(*found, tick, _path(self.nodes, len(self.nodes) - 1))
        return False

    def fresh(self, key: bytes, tick: int) -> bool:
        """Whether a state of `key` at `tick` is to be explored: not met yet, or only later (a state
        met again as late or later has its runs covered by the earlier one's, docs/VERIFY.md)."""
        explored = self.seen.get(key)
        if explored is not None and explored >= tick:
            return False
        self.seen[key] = tick
        self.explored += 1
        return True

    def queued(self, parent: int, made: list[Choice]) -> int:
        self.nodes.append(_Node(parent, made))
        return len(self.nodes) - 1

    def done(self, exhausted: bool) -> Outcome:
        result = self.result
        result.states = self.explored + self.ends
        result.exhausted = exhausted
        result.seconds = time.perf_counter() - self.started
        return result


def _first(
    program: Program, options: RunOptions, chooser: Chooser, budget: Budget, given: Given
) -> tuple[Engine, Ended | None]:
    world = ChoosingWorld(chooser, budget.loss, budget.delay, budget.fail, given)
    made = first_state(program, options, chooser, world)
    if isinstance(made, Ended):
        return Engine([], world, program.dt, None), made
    for agent in made.agents:
        agent.rng = _RNG  # no stand-in or built-in draws from it: one for all, shared by every state
    return made, None


def _first_itself(live: Engine | None, snaps: Snapshots, data: bytes) -> Callable[[], Engine]:
    """A queued state for each run of its tick: the engine itself first when it was queued whole
    (unused yet: no copy to make), then copies loaded from `data`."""

    def engine_for() -> Engine:
        nonlocal live
        if live is not None:
            engine, live = live, None
            return engine
        copy: Engine = snaps.load(data)
        return copy

    return engine_for


def _all_prefixes(
    chooser: Chooser, run: Callable[[], tuple[Engine, Ended | None]]
) -> Iterator[tuple[Engine, Ended | None]]:
    pending: list[tuple[int, ...]] = [()]
    while pending:
        chosen = pending.pop()
        chooser.begin(chosen)
        outcome = run()
        pending.extend(chooser.siblings())
        yield outcome


def _path(nodes: list[_Node], index: int) -> list[Choice]:
    chain: list[list[Choice]] = []
    while index >= 0:
        chain.append(nodes[index].choices)
        index = nodes[index].parent
    return [c for made in reversed(chain) for c in made]
