"""Time the join-coverage check (docs/REFERENCE.md#parallel-states): parallel states of 6 regions with 5
outcomes each.

For each case: `hfsm-run --check` of the whole file in process (load, every check), the coverage
search alone, and a naive search over every combination for comparison. Rewrites the bench_checks
section of docs/PERFORMANCE.md (nothing else in that shared file).
Usage: .venv/bin/python tools/bench_checks.py [--repeats N] [--no-doc]
"""

from __future__ import annotations

import argparse
import contextlib
import itertools
import os
import platform
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from hfsm.checks.coverage import Rule, uncovered
from hfsm.errors import UserError
from hfsm.load import load

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
REGIONS = [f"r{i}" for i in range(6)]
OUTCOMES = [f"o{j}" for j in range(5)]


def one_gap() -> list[Rule]:
    """Each rule accepts all but o0 of one region: only all-o0 is left uncovered."""
    return [{r: frozenset(OUTCOMES[1:])} for r in REGIONS]


def per_outcome() -> list[Rule]:
    """One rule per outcome of the first region, then per outcome of each other: covered."""
    return [{r: frozenset({o})} for r in REGIONS for o in OUTCOMES]


def pairs_differ() -> list[Rule]:
    """A rule for every two regions that ended differently: only the 5 all-equal combinations are left."""
    return [
        {a: frozenset({x}), b: frozenset({y})}
        for a, b in itertools.combinations(REGIONS, 2)
        for x in OUTCOMES
        for y in OUTCOMES
        if x != y
    ]


CASES: dict[str, Callable[[], list[Rule]]] = {
    "one gap (6 rules)": one_gap,
    "covered (30 rules)": per_outcome,
    "5 gaps (300 rules)": pairs_differ,
}


def machine_text(rules: list[Rule]) -> str:
    lines = ["outcomes: [done]", "states:", "  s:", "    parallel:"]
    lines += [f"      {r}: {{do: five}}" for r in REGIONS]
    lines.append("    join:")
    for rule in rules:
        when = ", ".join(f"{r}: [{', '.join(sorted(o))}]" for r, o in rule.items())
        lines.append(f"      - {{when: {{{when}}}, then: done}}")
    return "\n".join(lines) + "\n"


FIVE = (
    "outcomes: [" + ", ".join(OUTCOMES) + "]\nstates:\n  w: {do: wait, with: {seconds: 1}, on: {done: o0}}\n"
)


def median_seconds(fn: Callable[[], object], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        begin = time.perf_counter()
        fn()
        times.append(time.perf_counter() - begin)
    return statistics.median(times)


def naive(rules: list[Rule]) -> int:
    regions = dict.fromkeys(REGIONS, OUTCOMES)
    return sum(
        1
        for combo in itertools.product(*regions.values())
        if not any(
            all(dict(zip(REGIONS, combo, strict=True))[r] in o for r, o in rule.items()) for rule in rules
        )
    )


def check_file(path: Path) -> None:
    with contextlib.suppress(UserError):  # a join that can hang is what these files are made to have
        load([path])


def rows(repeats: int) -> list[tuple[str, float, float, float]]:
    out = []
    with tempfile.TemporaryDirectory() as folder:
        Path(folder, "five.yaml").write_text(FIVE, encoding="utf-8")
        for name, make in CASES.items():
            rules = make()
            path = Path(folder, "top.yaml")
            path.write_text(machine_text(rules), encoding="utf-8")
            whole = median_seconds(lambda p=path: check_file(p), repeats)  # type: ignore[misc]
            search = median_seconds(lambda r=rules: uncovered(dict.fromkeys(REGIONS, OUTCOMES), r), repeats)  # type: ignore[misc]
            brute = median_seconds(lambda r=rules: naive(r), max(1, repeats // 5))  # type: ignore[misc]
            out.append((name, whole, search, brute))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="runs per row; the median is kept")
    parser.add_argument("--no-doc", action="store_true", help="do not touch PERFORMANCE.md")
    args = parser.parse_args()
    table = rows(args.repeats)
    lines = [
        f"Measured by `tools/bench_checks.py` on {platform.machine()}, {os.cpu_count()} CPUs, "
        f"Python {platform.python_version()}: a parallel state of 6 regions with 5 outcomes each "
        f"(15,625 combinations); median of {args.repeats}.",
        "",
        "| rules | whole `--check` in process, ms | coverage search, ms | naive search, ms | naive/search |",
        "|---|---|---|---|---|",
    ]
    lines += [
        f"| {name} | {1000 * w:.1f} | {1000 * s:.2f} | {1000 * b:.0f} | {b / s:.0f}x |"
        for name, w, s, b in table
    ]
    worst = max(w for _, w, _, _ in table)
    verdict = (
        f"slowest whole check of a 6x5 parallel state: **{1000 * worst:.0f} ms** (target: well under 1 s)"
    )
    lines += ["", f"- {verdict}"]
    print("\n".join(lines))
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_checks", lines)
    print(verdict)


if __name__ == "__main__":
    main()
