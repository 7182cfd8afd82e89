"""The search on several processes: workers run states' ticks, the search itself stays in one.

The search (`search.Search`) keeps the queue, the keys seen and the tree of choices; it sends the
states at the head of its queue, as bytes, to worker processes forked from it (so they hold the
very program, stand-ins and table of shared objects its copies refer to). A worker loads each
state, runs every successor (`answers`), and sends back for each what the search needs to
decide: the choices made, the outcomes reached, a violation, or the key and bytes of the state
reached. The search takes the answers in the order of its queue, as it would have run them itself,
so what it explores, finds and reports is the same whatever the number of workers; only, every
successor is run on a copy loaded from bytes (one process cannot run a state queued as an engine
in another), as the search on one process does past its queue's first `LIVE` engines. With keys
as bytes, a copy may pickle to other bytes than the engine it was copied from (docs/VERIFY.md,
*States*), so a search on one process may count a few more states; the verdict is the same.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import signal
import traceback
from collections import deque
from collections.abc import Callable, Iterator
from multiprocessing.connection import Connection
from typing import Any, Protocol, TypeAlias, TypeVar

from hfsm.runtime.engine import Engine
from hfsm.verify.choices import Choice, Chooser
from hfsm.verify.snapshot import Snapshots, digest
from hfsm.verify.step import Ended, discard, successors, top_outcomes

# What a worker says of one successor: the choices made, the top outcomes reached, a violation
# (kind, agent, text), the key and bytes of the state reached (None: the run ended), its tick.
Found: TypeAlias = "tuple[str, str, str] | None"
Run: TypeAlias = tuple[Engine, "Ended | None"]  # an engine after a tick, and why its run cannot go on
Reached: TypeAlias = tuple[list[Choice], tuple[str, ...], Found, "bytes | None", "bytes | None", int]

Result = TypeVar("Result", covariant=True)


class Search(Protocol[Result]):
    """What of the search (`search.Search`) its workers and the loop that feeds them use."""

    ends: int
    live_cap: int

    @property
    def chooser(self) -> Chooser: ...
    @property
    def snaps(self) -> Snapshots: ...
    @property
    def check(self) -> Callable[[Engine, Ended | None], Found]: ...
    @property
    def key(self) -> Callable[[Engine], bytes] | None: ...
    @property
    def queue(self) -> deque[tuple[int, bytes, Engine | None]]: ...
    @property
    def top_outcomes(self) -> set[str]: ...
    @property
    def last_tick(self) -> int: ...
    def roots(self, first: Callable[[], Run]) -> Iterator[Run]: ...
    def visit(self, engine: Engine, ended: Ended | None, parent: int) -> bool: ...
    def violated(self, found: tuple[str, str, str], tick: int, parent: int, made: list[Choice]) -> bool: ...
    def fresh(self, key: bytes, tick: int) -> bool: ...
    def queued(self, parent: int, made: list[Choice]) -> int: ...
    def over(self) -> bool: ...
    def done(self, exhausted: bool) -> Result: ...


CHUNK = 32  # states sent to a worker at once
AHEAD = 2  # chunks a worker may hold, so that it never waits for the search


def answers(search: Search[Any], data: bytes) -> list[Reached]:
    """What the search needs of every successor of the state `data`, in the order it runs them;
    after a violation, none more (the search stops there)."""
    snaps = search.snaps
    found: list[Reached] = []
    for engine, ended in successors(search.chooser, lambda: snaps.load(data), search.last_tick):
        found.append(_reached(search, engine, ended))
        if found[-1][2] is not None:
            break
    return found


def _reached(search: Search[Any], engine: Engine, ended: Ended | None) -> Reached:
    made = list(search.chooser.made)
    outcomes = tuple(top_outcomes(engine))
    violation = search.check(engine, ended)
    key = data = None
    if violation is None and ended is None and engine.running > 0:
        data = search.snaps.dump(engine)
        key = digest(data) if search.key is None else search.key(engine)
    tick = engine.tick
    discard(engine)
    return made, outcomes, violation, key, data, tick


def take(search: Search[Any], parent: int, reached: Reached) -> bool:
    """What `Search.visit` does with a successor, from a worker's answer; False on a violation."""
    made, outcomes, violation, key, data, tick = reached
    search.top_outcomes.update(outcomes)
    if violation is not None:
        return search.violated(violation, tick, parent, made)
    if key is None or data is None:
        search.ends += 1
    elif search.fresh(key, tick):
        search.queue.append((search.queued(parent, made), data, None))
    return True


class _Worker:
    def __init__(self, search: Search[Any]) -> None:
        here, there = multiprocessing.Pipe()
        self.conn = here
        self.held = 0  # chunks sent and not answered
        fork = multiprocessing.get_context("fork")
        self.process = fork.Process(target=_serve, args=(there, search), daemon=True)
        self.process.start()
        there.close()

    def send(self, chunk: list[bytes]) -> None:
        self.held += 1
        self.conn.send(chunk)

    def answer(self) -> list[list[Reached]]:
        self.held -= 1
        got: Any = self.conn.recv()
        if isinstance(got, str):
            raise RuntimeError(f"a worker of the search failed:\n{got}")
        return got  # type: ignore[no-any-return]

    def stop(self) -> None:
        with contextlib.suppress(OSError):  # a worker that died has closed its end
            self.conn.send(None)
        self.conn.close()
        self.process.join(timeout=1)  # it may be running a chunk the search no longer needs
        if self.process.is_alive():
            self.process.kill()
            self.process.join()


def _serve(conn: Connection, search: Search[Any]) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the search stops its workers itself
    while True:
        try:
            chunk = conn.recv()
        except (EOFError, OSError):
            return
        if chunk is None:
            return
        answer: list[list[Reached]] | str
        try:
            answer = [answers(search, data) for data in chunk]
        except Exception:  # told to the search, which raises it
            answer = traceback.format_exc()
        try:
            conn.send(answer)
        except OSError:  # the search stopped (a violation, its budget) and closed its end
            return


def run(search: Search[Result], workers: int, first: Callable[[], Run]) -> Result:
    """`Search.run`, the ticks run by `workers` processes."""
    search.live_cap = 0
    for engine, ended in search.roots(first):
        if not search.visit(engine, ended, -1):
            return search.done(False)
    pool = [_Worker(search) for _ in range(workers)]
    flying: deque[tuple[_Worker, list[int]]] = deque()
    try:
        while True:
            _dispatch(search, pool, flying)
            if not flying:
                return search.done(True)
            worker, indexes = flying.popleft()
            for index, reached in zip(indexes, worker.answer(), strict=True):
                if search.over():
                    return search.done(False)
                for one in reached:
                    if not take(search, index, one):
                        return search.done(False)
    finally:
        for worker in pool:
            worker.stop()


def _dispatch(search: Search[Any], pool: list[_Worker], flying: deque[tuple[_Worker, list[int]]]) -> None:
    queue = search.queue
    while queue:
        worker = min(pool, key=lambda w: w.held)
        if worker.held >= AHEAD:
            return
        size = max(1, min(CHUNK, len(queue) // len(pool)))
        chunk = [queue.popleft() for _ in range(min(size, len(queue)))]
        worker.send([data for _, data, _ in chunk])
        flying.append((worker, [index for index, _, _ in chunk]))
