"""tools/bench_engine.py at tiny sizes, in process, without the peers: its checks pass, and catch a lie."""

from __future__ import annotations

from dataclasses import asdict
from pathlib import Path
from typing import Any

import pytest
from helpers import load_tool

ENGINE = load_tool("bench_engine")

from bench.harness import CheckFailed, count_calls, measure  # noqa: E402
from bench.hfsm_workloads import HfsmBench  # noqa: E402
from bench.peers import ADAPTERS  # noqa: E402
from bench.worker import Settings, _peer_workloads  # noqa: E402


@pytest.fixture
def bench(tmp_path: Path) -> HfsmBench:
    return HfsmBench(tmp_path, chain_states=20)


def test_hfsm_workloads_run_and_pass_their_checks(bench: HfsmBench) -> None:
    works = [
        bench.flat(40),
        bench.nested(15),
        bench.flat(20, "list"),
        bench.nested(10, "list"),
        bench.flat(10, "jsonl"),
        bench.nested(5, "jsonl"),
        bench.chain_run(2),
        bench.chain_load(),
        bench.chain_compile(),
        bench.parallel(12),
    ]
    for work in works:
        timing = measure(work, repeats=1, budget=0.0)
        assert timing.n == work.n and timing.seconds > 0


@pytest.mark.parametrize("kind", ["flat", "nested"])
@pytest.mark.parametrize("trace", ["none", "list"])
def test_checks_catch_a_wrong_count(bench: HfsmBench, kind: str, trace: str) -> None:
    work = getattr(bench, kind)(12, trace)
    handle = work.prepare(12)
    work.execute(handle)
    with pytest.raises(CheckFailed):
        work.check(handle, 13)


def test_w4_check_catches_a_wrong_count(bench: HfsmBench) -> None:
    work = bench.parallel(12)
    handle = work.prepare(12)
    work.execute(handle)
    work.check(handle, 12)
    with pytest.raises(CheckFailed):
        work.check(handle, 11)


def test_calls_per_transition_are_counted(bench: HfsmBench) -> None:
    flat = count_calls(bench.flat(1), 50, 100)
    nested = count_calls(bench.nested(1), 50, 100)
    assert 0 < flat.python < nested.python < 1000


def test_peer_harness_with_the_floor() -> None:
    settings = Settings(w1=200, w2=50, laps=1)
    for work in _peer_workloads(ADAPTERS["floor"], settings).values():
        assert measure(work, repeats=1, budget=0.001).n >= 1


def test_section_renders_from_a_report() -> None:
    report: dict[str, Any] = {
        "lib": "hfsm",
        "name": "hfsm",
        "version": "0",
        "cells": {"w1": {"seconds": 1e-6, "n": 10}, "w2": {"seconds": 5e-6, "n": 10}},
        "calls": {"w1": [16.0, 7.0]},
        "errors": {},
        "skipped": "",
    }
    pooled = {"hfsm": ENGINE.rep.pool([report, report])}
    text = ENGINE.section(pooled, Settings(), "cmd", 2, 1.0)
    assert (
        "1.00 µs, **met**" in text and "5.00 µs, **not met**" in text and "| hfsm | 0 | 1.00 | 5.00 |" in text
    )


def test_a_peer_that_is_not_installed_is_skipped(monkeypatch: pytest.MonkeyPatch) -> None:
    import bench.worker

    monkeypatch.setitem(bench.worker.IMPORTS, "sismic", "no_such_module_for_bench")
    report = bench.worker.run_peer("sismic", Settings())
    assert "not importable" in report.skipped and not report.cells
    pooled = {"sismic": ENGINE.rep.pool([asdict(report)])}
    assert "| sismic | not installed |" in "\n".join(ENGINE.rep.table(pooled))
