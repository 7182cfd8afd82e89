"""Choice points: where the world (or a stand-in) may go one way or another, and who decides.

The engine is deterministic given these choices. A search asks a `Chooser` that takes each option
in turn; a replay asks a `Schedule` that answers as a counterexample's file says. Both count the
choice points of a run in the same order (`Counter.n`, kept in the world so it is part of a state).
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol


class Counter(Protocol):
    n: int  # choice points asked so far in the run


@dataclass(frozen=True)
class Choice:
    """One choice a run made: its number, tick, kind ("message", "stand_in", "fail"), what it was
    about, and what was chosen (as JSON)."""

    n: int
    tick: int
    kind: str
    what: str
    choice: dict[str, Any]

    def as_json(self, dt: float) -> dict[str, Any]:
        return {
            "n": self.n,
            "t": round(self.tick * dt, 9),
            "kind": self.kind,
            "what": self.what,
            **self.choice,
        }


class Decider(Protocol):
    def pick(
        self,
        counter: Counter,
        tick: int,
        kind: str,
        what: str,
        options: Sequence[dict[str, Any]],
        deferred: Collection[int] = (),
    ) -> dict[str, Any]:
        """One of `options` (the first is what a world without choices would do). A search may
        leave the options numbered in `deferred` untried unless `Chooser.restore` asks for them."""


@dataclass
class Chooser:
    """The search's decider: within one tick, takes `prefix[i]` at the i-th point, then the first.

    Options a point defers are not among `siblings()` but kept in `held`, for the search to run
    when `restore` says so (docs/VERIFY.md, *Failures that change nothing*)."""

    prefix: Sequence[int] = ()
    taken: list[int] = field(default_factory=list)
    arities: list[int] = field(default_factory=list)
    made: list[Choice] = field(default_factory=list)
    deferred: dict[int, Collection[int]] = field(default_factory=dict)  # by point
    held: list[tuple[int, ...]] = field(default_factory=list)
    restore: bool = False  # a run of this state ended an agent: the held prefixes must be run too

    def begin(self, prefix: Sequence[int]) -> None:
        self.prefix = prefix
        self.taken = []
        self.arities = []
        self.made = []
        self.deferred = {}

    def pick(
        self,
        counter: Counter,
        tick: int,
        kind: str,
        what: str,
        options: Sequence[dict[str, Any]],
        deferred: Collection[int] = (),
    ) -> dict[str, Any]:
        n = counter.n
        counter.n += 1
        if len(options) == 1:
            return options[0]
        i = len(self.taken)
        index = self.prefix[i] if i < len(self.prefix) else 0
        if deferred:
            self.deferred[i] = deferred
        self.taken.append(index)
        self.arities.append(len(options))
        chosen = options[index]
        if index or kind == "stand_in":
            self.made.append(Choice(n, tick, kind, what, chosen))
        return chosen

    def siblings(self) -> list[tuple[int, ...]]:
        """The prefixes still to try after a run that took the first option past `prefix`."""
        found: list[tuple[int, ...]] = []
        for i in range(len(self.prefix), len(self.taken)):
            deferred = self.deferred.get(i, ())
            for j in range(1, self.arities[i]):
                (self.held if j in deferred else found).append((*self.taken[:i], j))
        return found


class Schedule:
    """The replay's decider: what the file says at the choice points it lists, else the first option."""

    def __init__(self, choices: Sequence[dict[str, Any]]) -> None:
        self.by_n = {int(c["n"]): c for c in choices if c.get("kind") != "fail"}

    def pick(
        self,
        counter: Counter,
        tick: int,
        kind: str,
        what: str,
        options: Sequence[dict[str, Any]],
        deferred: Collection[int] = (),
    ) -> dict[str, Any]:
        n = counter.n
        counter.n += 1
        entry = self.by_n.get(n)
        if entry is None:
            return options[0]
        if entry.get("kind") != kind:
            raise ValueError(f"the schedule's choice {n} is a {entry.get('kind')}, but the run asks a {kind}")
        return {k: v for k, v in entry.items() if k not in ("n", "t", "kind", "what")}
