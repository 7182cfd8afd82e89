"""One library in one process: every workload through the harness, results as a JSON-able dict."""

from __future__ import annotations

import tempfile
import traceback
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import asdict, dataclass, field
from functools import partial
from itertools import repeat
from pathlib import Path
from typing import Any

from bench.harness import Calls, Workload, count_calls, expect, measure
from bench.peers import ADAPTERS, IMPORTS, Adapter, Built, Step, chain_spec, counts, flat_spec, nested_spec
from bench.w4 import PEERS as W4_PEERS
from bench.w4 import peer_workload as w4_workload

CHAIN_STATES = 500

# Cells (keys of Report.cells): w1, w2, w3_load, w3_compile (hfsm), w3_chain, and hfsm's trace-on
# w1_list, w2_list (ListTrace) and w1_jsonl, w2_jsonl (JSONL to /dev/null). Values are seconds per
# unit: per transition, or per build for w3_load and w3_compile.


@dataclass(frozen=True)
class Settings:
    repeats: int = 5
    budget: float = 0.4  # seconds a peer's repeat should take (its n is sized from the warm-up)
    w1: int = 100_000
    w2: int = 20_000
    laps: int = 20  # W3 chain runs (500 transitions each)
    w4: int = 20_000  # joins
    trace_w1: int = 20_000
    trace_w2: int = 5_000
    calls: bool = True


@dataclass
class Report:
    lib: str
    name: str
    version: str = ""
    cells: dict[str, dict[str, float]] = field(default_factory=dict)  # cell -> {seconds, n}
    calls: dict[str, list[float]] = field(default_factory=dict)  # cell -> [python, builtin] per dispatch
    errors: dict[str, str] = field(default_factory=dict)
    skipped: str = ""


def _cell(report: Report, cell: str, work: Workload[Any], settings: Settings, budget: float) -> None:
    try:
        timing = measure(work, repeats=settings.repeats, budget=budget)
    except Exception as exc:
        report.errors[cell] = f"{type(exc).__name__}: {exc}"
        traceback.print_exc()
        return
    report.cells[cell] = {"seconds": timing.seconds, "n": timing.n}


def _calls(report: Report, cell: str, counted: Callable[[], Calls]) -> None:
    try:
        calls = counted()
    except Exception as exc:
        report.errors[f"calls {cell}"] = f"{type(exc).__name__}: {exc}"
        return
    report.calls[cell] = [calls.python, calls.builtin]


# --- hfsm ----------------------------------------------------------------------------------------


@contextmanager
def _folder() -> Iterator[Path]:
    with tempfile.TemporaryDirectory(prefix="bench_engine_") as name:
        yield Path(name)


def run_hfsm(settings: Settings) -> Report:
    from importlib.metadata import version

    from bench.hfsm_workloads import HfsmBench

    report = Report("hfsm", "hfsm", version("hfsm"))
    with _folder() as folder:
        bench = HfsmBench(folder, chain_states=CHAIN_STATES)
        cells: dict[str, Workload[Any]] = {
            "w1": bench.flat(settings.w1),
            "w2": bench.nested(settings.w2),
            "w3_load": bench.chain_load(),
            "w3_compile": bench.chain_compile(),
            "w3_chain": bench.chain_run(settings.laps),
            "w4": bench.parallel(settings.w4),
            "w1_list": bench.flat(settings.trace_w1, "list"),
            "w2_list": bench.nested(settings.trace_w2, "list"),
            "w1_jsonl": bench.flat(settings.trace_w1, "jsonl"),
            "w2_jsonl": bench.nested(settings.trace_w2, "jsonl"),
        }
        for cell, work in cells.items():
            _cell(report, cell, work, settings, 0.0)
        if settings.calls:
            _calls(report, "w1", lambda: count_calls(bench.flat(1), 1000, 2000))
            _calls(report, "w2", lambda: count_calls(bench.nested(1), 1000, 2000))
            _calls(report, "w4", lambda: count_calls(bench.parallel(1), 1000, 2000))
            _calls(
                report, "w3_chain", lambda: count_calls(bench.chain_run(1), CHAIN_STATES, 2 * CHAIN_STATES)
            )
    return report


# --- peers ---------------------------------------------------------------------------------------


@dataclass
class Machines:
    built: list[Built]
    steps: list[Step]
    per_machine: int  # dispatches on each
    before: list[tuple[int, int]]


def _dispatch(
    adapter: Adapter, make: Callable[[], Any], event: str, per_machine: int | None
) -> Callable[[int], Machines]:
    """prepare(n): one machine taking n dispatches, or n // per_machine machines taking per_machine each."""

    def prepare(n: int) -> Machines:
        k = n if per_machine is None else per_machine
        built = [adapter.build(make()) for _ in range(n // k)]
        steps = [adapter.stepper(b, event) for b in built]
        return Machines(built, steps, k, [counts(adapter, b) for b in built])

    return prepare


def _execute(m: Machines) -> None:
    k = m.per_machine
    for step in m.steps:
        for _ in repeat(None, k):
            step()


def _leaf_check(
    adapter: Adapter, leaf: Callable[[int], str], callbacks: int
) -> Callable[[Machines, int], None]:
    def check(m: Machines, n: int) -> None:
        k = m.per_machine
        for built, before in zip(m.built, m.before, strict=True):
            got = adapter.leaf(built)
            expect(got == leaf(k), f"{adapter.name}: leaf {got!r} after {k} dispatches, expected {leaf(k)!r}")
            entries, exits = counts(adapter, built)
            done = (entries - before[0], exits - before[1])
            want = (callbacks * k, callbacks * k)
            expect(
                done == want, f"{adapter.name}: entries/exits {done} after {k} dispatches, expected {want}"
            )

    return check


def _peer_workloads(adapter: Adapter, settings: Settings) -> dict[str, Workload[Any]]:
    chain = chain_spec(CHAIN_STATES)
    return {
        "w1": Workload(
            _dispatch(adapter, flat_spec, "toggle", None),
            _execute,
            _leaf_check(adapter, lambda k: "AB"[k % 2], 0),
            settings.w1,
            calibrate=1000,
        ),
        "w2": Workload(
            _dispatch(adapter, nested_spec, "go", None),
            _execute,
            _leaf_check(adapter, lambda k: ("P1a", "Q1a")[k % 2], 3),
            settings.w2,
            calibrate=200,
        ),
        "w3_load": _yaml_build(adapter, adapter.chain_yaml(chain)),
        "w3_chain": Workload(
            _dispatch(adapter, lambda: chain, "next", CHAIN_STATES),
            _execute,
            _leaf_check(adapter, lambda k: "end", 0),
            settings.laps * CHAIN_STATES,
            step=CHAIN_STATES,
            calibrate=CHAIN_STATES,
        ),
    }


def _yaml_build(adapter: Adapter, text: str) -> Workload[list[Built]]:
    def check(out: list[Built], n: int) -> None:
        expect(len(out) == 1, "one build")
        got = adapter.leaf(out[0])
        expect(got == "s0", f"{adapter.name}: built from YAML in {got!r}, expected 's0'")
        adapter.stepper(out[0], "next")()
        got = adapter.leaf(out[0])
        expect(got == "s1", f"{adapter.name}: after one 'next' in {got!r}, expected 's1'")

    return Workload(lambda n: [], lambda out: out.append(adapter.from_yaml(text)), check, 1)


def run_peer(lib: str, settings: Settings) -> Report:
    from importlib import import_module
    from importlib.metadata import PackageNotFoundError, version

    adapter = ADAPTERS[lib]
    report = Report(lib, adapter.name)
    try:
        import_module(IMPORTS[lib])
        report.version = version(adapter.dist) if adapter.dist else "-"
    except (ImportError, PackageNotFoundError) as exc:
        report.skipped = f"not importable ({exc}); pip install -r tools/bench-requirements.txt"
        return report
    workloads = _peer_workloads(adapter, settings)
    if lib in W4_PEERS:
        workloads["w4"] = w4_workload(lib, settings.w4)
    for cell, work in workloads.items():
        _cell(report, cell, work, settings, settings.budget)
    if settings.calls:
        sizes = {"w1": (200, 1200), "w2": (200, 1200), "w3_chain": (500, 1000), "w4": (200, 1200)}
        for cell, (small, large) in sizes.items():
            if cell not in workloads:
                continue
            work = workloads[cell]
            _calls(report, cell, partial(count_calls, work, small, large))
    return report


def run_worker(lib: str, settings: Settings) -> dict[str, Any]:
    report = run_hfsm(settings) if lib == "hfsm" else run_peer(lib, settings)
    return asdict(report)
