"""A live operator's decision takes effect at the start of the tick after the one it came in: the
run looks at the live queue first thing in every tick (and a paced live run of a static world runs
every tick, so none is skipped past a decision)."""

from __future__ import annotations

import queue
from pathlib import Path
from typing import Any

from helpers import ListTrace
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.autonomy import Decision
from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.program import Program
from hfsm.runtime.run import RunOptions, run
from hfsm.world import NullWorld

WAIT = """\
outcomes: [done]
states:
  idle: {do: wait, with: {seconds: 2}, on: {done: again}}
  again: {do: wait, with: {seconds: 2}, on: {done: done}}
"""


class Page(ListTrace):
    """A trace sink that, at the end of tick `at` (when the run flushes it), sends a pause."""

    def __init__(self, live: queue.Queue[Decision], at: int) -> None:
        super().__init__()
        self.live, self.at, self.ticks = live, at, 1  # tick 0's records go out with tick 1's flush

    def flush(self) -> None:
        if self.ticks == self.at:
            self.live.put(Decision(0.0, "pause"))
            self.live.put(Decision(0.0, "resume"))
        self.ticks += 1


def _run(folder: Path, at: int, every_tick: bool) -> list[dict[str, Any]]:
    path = folder / "idle.yaml"
    path.write_text(WAIT)
    loaded = load([path], registry=Registry())
    live: queue.Queue[Decision] = queue.Queue()
    sink = Page(live, at)
    options = RunOptions("idle", ["robot"], {}, live=live, every_tick=every_tick)
    run(Program(loaded.machines, Registry(), 0.05), NullWorld(), options, sink)
    return sink.records


@settings(max_examples=15, deadline=None)
@given(st.integers(min_value=1, max_value=30))
def test_a_decision_acts_in_the_next_tick(at: int) -> None:
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        records = _run(Path(folder), at, every_tick=True)
    ops = [(r["t"], r["do"]) for r in records if r["kind"] == "operator"]
    assert ops == [(round((at + 1) * 0.05, 9), "pause"), (round((at + 1) * 0.05, 9), "resume")]


def test_without_every_tick_a_static_world_skips_to_the_next_thing_that_can_happen(tmp_path: Path) -> None:
    ops = [(r["t"], r["do"]) for r in _run(tmp_path, 1, every_tick=False) if r["kind"] == "operator"]
    # sent at the end of 2.0 s (the first wait's end), taken at the second's: why a paced live run runs every tick
    assert ops == [(4.0, "pause"), (4.0, "resume")]
