"""The timing loop every library goes through, and the Python-call counter.

Timing (docs/PERFORMANCE.md, bench_engine section): a discarded warm-up, then the best of
`repeats`; each repeat prepares a fresh machine outside the timer, runs `gc.collect()`, times
`execute` with `time.perf_counter` (the collector stays on, as in an application) and then runs
the workload's correctness check, so a library that skips work fails instead of looking fast.
"""

from __future__ import annotations

import gc
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from types import FrameType
from typing import Any, Generic, TypeVar

H = TypeVar("H")


class CheckFailed(Exception):
    """A workload's result is not what the workload must produce."""


def expect(condition: bool, message: str) -> None:
    if not condition:
        raise CheckFailed(message)


@dataclass(frozen=True)
class Workload(Generic[H]):
    """`prepare(n)` builds a fresh handle (untimed), `execute(h)` does n units, `check(h, n)` verifies."""

    prepare: Callable[[int], H]
    execute: Callable[[H], object]
    check: Callable[[H, int], None]
    n: int  # units (transitions, builds) per repeat, or the most of them when sizing by budget
    step: int = 1  # n stays a multiple of this when sized by budget
    calibrate: int = 0  # > 0: size n so that one repeat takes about `budget` s, from a run of this size


@dataclass(frozen=True)
class Timing:
    seconds: float  # per unit, best of the repeats
    n: int  # units per repeat


def _once(work: Workload[H], n: int) -> float:
    handle = work.prepare(n)
    gc.collect()
    begin = time.perf_counter()
    work.execute(handle)
    elapsed = time.perf_counter() - begin
    work.check(handle, n)
    return elapsed


def _size(work: Workload[Any], budget: float) -> int:
    """The warm-up: at the calibration size when sizing by budget, else at full size."""
    if work.calibrate <= 0:
        _once(work, work.n)
        return work.n
    trial = min(work.n, work.calibrate)
    per_unit = _once(work, trial) / trial
    fitted = int(budget / per_unit) // work.step * work.step if per_unit > 0 else work.n
    return max(trial, min(work.n, fitted))


def measure(work: Workload[Any], *, repeats: int, budget: float) -> Timing:
    n = _size(work, budget)
    best = min(_once(work, n) for _ in range(repeats))
    return Timing(best / n, n)


@dataclass(frozen=True)
class Calls:
    python: float  # Python function calls per unit
    builtin: float  # C function calls per unit


def _counted(work: Workload[H], n: int) -> tuple[int, int]:
    handle = work.prepare(n)
    counts = [0, 0]

    def profile(frame: FrameType, event: str, arg: Any) -> None:
        if event == "call":
            counts[0] += 1
        elif event == "c_call":
            counts[1] += 1

    sys.setprofile(profile)
    try:
        work.execute(handle)
    finally:
        sys.setprofile(None)
    work.check(handle, n)
    return counts[0], counts[1]


def count_calls(work: Workload[Any], small: int, large: int) -> Calls:
    """Calls per unit from two sizes: (calls(large) - calls(small)) / (large - small).

    The difference cancels what a run does once (starting a machine, the loop's set-up), so the
    figure is the steady per-dispatch cost. Deterministic: no timing noise.
    """
    _counted(work, small)  # warm caches (first-call imports, lazily built tables)
    py_small, c_small = _counted(work, small)
    py_large, c_large = _counted(work, large)
    units = large - small
    return Calls((py_large - py_small) / units, (c_large - c_small) / units)
