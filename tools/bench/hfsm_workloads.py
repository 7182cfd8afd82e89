"""hfsm's side of bench_engine: the workload machines as YAML files, run in process.

- W1 flat: `a` and `b`, each a one-tick `wait`, back and forth; the machine `timer` ends the run
  after exactly n transitions (one a tick).
- W2 nested: top `a`/`b` each call `bench_w2_mid`, which calls `bench_w2_leaf`, which waits one tick
  and ends; every tick leaves three states (leaf, mid, top) and enters three.
- W4 parallel: see bench/w4.py; a unit is one join of four regions.
- W3 chain: `s0 -> s1 -> ... -> s{k-1} -> done`, each a one-tick `wait`; timed: `hfsm.load.load`
  (read, check), `Program` (compile), and running it.

Checks use what a run returns: its outcome, and per-behaviour counts of how each call ended
(`RunResult.stats`), which count every transition; with a ListTrace also the records.
"""

from __future__ import annotations

import os
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from bench.harness import Workload, expect
from bench.w4 import HFSM as W4
from bench.w4 import REGIONS
from hfsm.load import Loaded, load
from hfsm.registry import Registry
from hfsm.runtime.program import Program, span_ticks
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.trace import JsonlTrace, ListTrace, TraceSink
from hfsm.world import NullWorld

DT = 0.05
AGENT = "robot"
TRACES = ("none", "list", "jsonl")

W1 = """\
doc: bench_engine W1, flat. Two one-tick waits back and forth until the timer fires.
params:
  limit: {type: float, default: 1.0}
outcomes: [timeout]
timer: "${params.limit}"
states:
  a: {do: wait, with: {seconds: 0.05}, on: {done: b}}
  b: {do: wait, with: {seconds: 0.05}, on: {done: a}}
"""

W2 = """\
doc: bench_engine W2, nested. Each tick leaves leaf, mid and top states and enters three.
params:
  limit: {type: float, default: 1.0}
outcomes: [timeout]
timer: "${params.limit}"
states:
  a: {do: bench_w2_mid, on: {out: b}}
  b: {do: bench_w2_mid, on: {out: a}}
"""

W2_MID = """\
doc: bench_engine W2, middle level.
outcomes: [out]
states:
  run: {do: bench_w2_leaf, on: {done: out}}
"""

W2_LEAF = """\
doc: bench_engine W2, leaf level. Waits one tick.
outcomes: [done]
states:
  hold: {do: wait, with: {seconds: 0.05}, on: {done: done}}
"""


def chain_yaml(states: int) -> str:
    lines = [
        f"doc: bench_engine W3, a chain of {states} one-tick waits.",
        "outcomes: [done]",
        "states:",
    ]
    for i in range(states):
        to = f"s{i + 1}" if i + 1 < states else "done"
        lines.append(f"  s{i}: {{do: wait, with: {{seconds: 0.05}}, on: {{done: {to}}}}}")
    return "\n".join(lines) + "\n"


def limit_for(transitions: int) -> float:
    """Timer seconds that fire in tick n + 1, after the transitions of ticks 1..n (timer wins in n + 1)."""
    seconds = (transitions + 0.5) * DT
    expect(span_ticks(seconds, DT) == transitions + 1, "timer arithmetic")
    return seconds


@dataclass
class Handle:
    program: Program
    options: RunOptions
    trace: TraceSink | None
    runs: int = 1
    result: RunResult | None = None


def _execute(h: Handle) -> None:
    for _ in range(h.runs):
        h.result = run(h.program, NullWorld(), h.options, h.trace)


def _sink(kind: str) -> TraceSink | None:
    if kind == "list":
        return ListTrace()
    if kind == "jsonl":
        return JsonlTrace(Path(os.devnull))
    return None


def _ended(h: Handle, outcome: str) -> dict[str, dict[str, int]]:
    """Close the trace, check the run ended in `outcome`; each behaviour's event counts."""
    if h.trace is not None:
        h.trace.close()
    result = h.result
    expect(result is not None and result.error is None, f"run failed: {result and result.error}")
    assert result is not None
    got = result.agents[AGENT].outcome
    expect(got == outcome, f"outcome {got!r}, expected {outcome!r}")
    return {name: dict(stats.events) for name, stats in result.stats[AGENT].items()}


def _records(trace: TraceSink | None) -> Counter[str] | None:
    return Counter(r["kind"] for r in trace.records) if isinstance(trace, ListTrace) else None


def check_flat(h: Handle, n: int) -> None:
    events = _ended(h, "timeout")
    expect(events == {"wait": {"done": n, "timeout": 1}}, f"W1 counts {events}, expected {n} transitions")
    kinds = _records(h.trace)
    if kinds is not None:  # per transition: event, exit, enter; start: top and a; end: timeout, 2 exits
        want = {"enter": n + 2, "exit": n + 2, "event": n, "timeout": 1}
        expect(kinds == want, f"W1 trace records {dict(kinds)}, expected {want}")


def check_nested(h: Handle, n: int) -> None:
    events = _ended(h, "timeout")
    want = {
        "wait": {"done": n, "timeout": 1},
        "bench_w2_leaf": {"done": n, "timeout": 1},
        "bench_w2_mid": {"out": n, "timeout": 1},
    }
    expect(events == want, f"W2 counts {events}, expected {n} transitions at each level")
    kinds = _records(h.trace)
    if kinds is not None:  # 3 events, 3 exits, 3 entries a transition
        want_kinds = {"enter": 3 * n + 4, "exit": 3 * n + 4, "event": 3 * n, "timeout": 1}
        expect(kinds == want_kinds, f"W2 trace records {dict(kinds)}, expected {want_kinds}")


def check_parallel(h: Handle, n: int) -> None:
    events = _ended(h, "timeout")
    want = {"wait": {"done": REGIONS * n, "timeout": REGIONS}}
    expect(events == want, f"W4 counts {events}, expected {REGIONS} region ends in each of {n} joins")


class HfsmBench:
    """Writes the machine files into `folder` and builds the workloads over them."""

    def __init__(self, folder: Path, *, chain_states: int = 500) -> None:
        self.folder = folder
        self.chain_states = chain_states
        texts = {
            "bench_w1": W1,
            "bench_w2": W2,
            "bench_w2_mid": W2_MID,
            "bench_w2_leaf": W2_LEAF,
            "bench_w3": chain_yaml(chain_states),
            "bench_w4": W4,
        }
        for name, text in texts.items():
            (folder / f"{name}.yaml").write_text(text, encoding="utf-8")
        self.registry = Registry()
        self._loaded: dict[str, Loaded] = {}

    def loaded(self, top: str) -> Loaded:
        """`top` loaded on first use (so that an older hfsm, without W4's parallel states, runs W1-W3)."""
        if top not in self._loaded:
            loaded = self._loaded[top] = load([self.folder / f"{top}.yaml"], registry=self.registry)
            expect(not loaded.warnings, f"{top}: warnings {[str(w) for w in loaded.warnings]}")
        return self._loaded[top]

    def _handle(self, top: str, params: dict[str, float], trace: str, runs: int = 1) -> Handle:
        program = Program(self.loaded(top).machines, self.registry, DT)
        options = RunOptions(top, [AGENT], params, 0, max_time=1e9)
        return Handle(program, options, _sink(trace), runs)

    def flat(self, n: int, trace: str = "none") -> Workload[Handle]:
        return Workload(
            lambda k: self._handle("bench_w1", {"limit": limit_for(k)}, trace), _execute, check_flat, n
        )

    def nested(self, n: int, trace: str = "none") -> Workload[Handle]:
        return Workload(
            lambda k: self._handle("bench_w2", {"limit": limit_for(k)}, trace), _execute, check_nested, n
        )

    def parallel(self, n: int) -> Workload[Handle]:
        return Workload(
            lambda k: self._handle("bench_w4", {"limit": limit_for(k)}, "none"), _execute, check_parallel, n
        )

    def chain_run(self, laps: int) -> Workload[Handle]:
        """Run the chain `laps` times; units: transitions (chain_states a lap)."""
        states = self.chain_states

        def check(h: Handle, n: int) -> None:
            events = _ended(h, "done")
            expect(events == {"wait": {"done": states}}, f"W3 chain counts {events}")

        return Workload(
            lambda k: self._handle("bench_w3", {}, "none", k // states),
            _execute,
            check,
            laps * states,
            states,
        )

    def chain_load(self) -> Workload[list[Loaded]]:
        """`hfsm.load.load` of the chain file: read, resolve, check; one unit a load."""
        path = self.folder / "bench_w3.yaml"
        return Workload(
            lambda k: [], lambda out: out.append(load([path], registry=Registry())), self._check_loaded, 1
        )

    def _check_loaded(self, out: list[Loaded], n: int) -> None:
        expect(len(out) == 1 and not out[0].warnings, "W3 load: one load, no warnings")
        states = out[0].machines["bench_w3"].model.states
        expect(len(states) == self.chain_states, f"W3 load: {len(states)} states")

    def chain_compile(self) -> Workload[list[Program]]:
        """`Program(...)` over the loaded chain: arcs to objects, timers to ticks, values to closures."""
        machines = self.loaded("bench_w3").machines

        def check(out: list[Program], n: int) -> None:
            expect(len(out[0].machines["bench_w3"].states) == self.chain_states, "W3 compile: states")

        return Workload(lambda k: [], lambda out: out.append(Program(machines, self.registry, DT)), check, 1)
