"""Benchmark hfsm's engine against Python state-machine peers and a dict-table floor, in one run.

Usage: .venv/bin/python tools/bench_engine.py [--rounds 3] [--quick] [--libs hfsm,floor,...]
                                               [--no-doc] [--json FILE]
(`make bench` installs the peers from tools/bench-requirements.txt first.)

Workloads (see tools/bench/ and docs/PERFORMANCE.md): W1 flat two-state toggle,
W2 three nested levels (3 exits and 3 entries a transition), W3 a 500-state chain (load from YAML,
and run), W4 a parallel state of four one-tick regions joined and re-entered (hfsm, transitions,
sismic). Each library runs in a fresh process per round (`--worker LIB`), rounds rotate the order;
a figure is the median over rounds of the best of 5 repeats after a warm-up. Prints a Markdown
section and writes it between the bench_engine markers of docs/PERFORMANCE.md.
Exits 1 when a correctness check failed.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import time
from dataclasses import asdict, replace
from datetime import date
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
TOOLS = ROOT / "tools"
if str(TOOLS) not in sys.path:
    sys.path.insert(0, str(TOOLS))

from bench import report as rep  # noqa: E402
from bench.worker import Settings, run_worker  # noqa: E402
from docsection import write_section  # noqa: E402

DOC = ROOT / "docs" / "PERFORMANCE.md"
LIBS = ["hfsm", "floor", "transitions", "python-statemachine", "sismic"]
QUICK = Settings(
    repeats=3, budget=0.05, w1=20_000, w2=5_000, laps=4, trace_w1=5_000, trace_w2=1_000, w4=2_000
)
WORKER_TIMEOUT = 600


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=3, help="fresh-process rounds per library (median)")
    parser.add_argument("--quick", action="store_true", help="smoke run: 1 round, small sizes, no doc")
    parser.add_argument("--libs", default=",".join(LIBS), help="comma-separated subset of " + ",".join(LIBS))
    parser.add_argument("--no-doc", action="store_true", help="do not rewrite docs/PERFORMANCE.md")
    parser.add_argument("--json", type=Path, help="also write every round's raw results here")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    parser.add_argument("--settings", help=argparse.SUPPRESS)
    return parser.parse_args(argv)


def spawn(lib: str, settings: Settings) -> dict[str, Any]:
    """Run one library's workloads in a fresh interpreter; its report, or one that says what failed."""
    command = [sys.executable, str(Path(__file__).resolve()), "--worker", lib]
    command += ["--settings", json.dumps(asdict(settings))]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=WORKER_TIMEOUT, check=False)
    except subprocess.TimeoutExpired:
        return _failed(lib, f"worker timed out after {WORKER_TIMEOUT} s")
    if done.stderr.strip():
        sys.stderr.write(done.stderr)
    lines = done.stdout.strip().splitlines()
    if done.returncode != 0 or not lines:
        return _failed(lib, f"worker exited {done.returncode}: {done.stderr.strip()[-500:]}")
    result: dict[str, Any] = json.loads(lines[-1])
    return result


def _failed(lib: str, why: str) -> dict[str, Any]:
    return {
        "lib": lib,
        "name": lib,
        "version": "",
        "cells": {},
        "calls": {},
        "errors": {"worker": why},
        "skipped": "",
    }


def run_rounds(libs: list[str], rounds: int, settings: Settings) -> dict[str, list[dict[str, Any]]]:
    results: dict[str, list[dict[str, Any]]] = {lib: [] for lib in libs}
    for r in range(rounds):
        order = libs[r % len(libs) :] + libs[: r % len(libs)]
        for lib in order:
            begin = time.perf_counter()
            got = spawn(lib, replace(settings, calls=r == 0))
            results[lib].append(got)
            state = got["skipped"] or ", ".join(got["errors"]) or "ok"
            print(
                f"round {r + 1}/{rounds}: {lib}: {time.perf_counter() - begin:.1f} s, {state}",
                file=sys.stderr,
            )
    return results


def hfsm_version() -> str:
    from importlib.metadata import version

    def git(*args: str) -> str:
        done = subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True, check=False)
        return done.stdout.strip()

    head = git("log", "-1", "--format=%h")
    dirty = " + uncommitted changes in hfsm/" if git("status", "--porcelain", "--", "hfsm") else ""
    return f"{version('hfsm')} ({head}{dirty})"


def section(
    pooled: dict[str, rep.Pooled], settings: Settings, command: str, rounds: int, elapsed: float
) -> str:
    hfsm = pooled.get("hfsm")
    skipped = [f"{p.name}: {p.skipped}" for p in pooled.values() if p.skipped]
    failed = [f"{p.name} {cell}: {why}" for p in pooled.values() for cell, why in p.errors.items()]
    lines = [
        "## Engine against its peers (bench_engine)",
        "",
        f"Measured by `tools/bench_engine.py` on {platform.machine()}, {os.cpu_count()} CPUs, "
        f"Python {platform.python_version()}, {date.today().isoformat()}; hfsm {hfsm_version()}.",
        f"Command: `{command}` (or `make bench`, which installs tools/bench-requirements.txt first); "
        f"{rounds} round(s), {elapsed:.0f} s in all.",
        "",
        "Targets (hfsm, trace off):",
        *rep.targets(hfsm),
        "",
        *rep.table(pooled),
        "",
        *_method(pooled, settings, rounds),
    ]
    if hfsm is not None and "w3_compile" in hfsm.value:
        lines.append(
            f"- hfsm W3 is `hfsm.load.load` (read, resolve, every check); compiling the loaded chain "
            f"(`Program`) takes another {rep.fmt(hfsm.value['w3_compile'])} ms."
        )
    lines += ["", "Cost relative to hfsm (each library's median / hfsm's median):", "", *rep.ratios(pooled)]
    lines += ["", "Python calls per dispatch, Python / C (`sys.setprofile`, noise-free):", ""]
    lines += [*rep.calls_table(pooled), "", *_calls_note()]
    lines += [f"- skipped: {s}" for s in skipped] + [f"- **FAILED** {f}" for f in failed]
    return "\n".join(lines)


def _method(pooled: dict[str, rep.Pooled], settings: Settings, rounds: int) -> list[str]:
    return [
        f"- Each figure: median over rounds of the best of {settings.repeats} repeats after a warm-up; "
        "each library in a fresh process per round (order rotated); a fresh machine and `gc.collect()` "
        "before each repeat, collector on while timing; spread over rounds (max/min) "
        f"{rep.spread(pooled, rounds)}.",
        "- Every repeat is checked afterwards: peers' final state and, in W2, 3 entry and 3 exit callbacks "
        "per dispatch; hfsm's run outcome (`timeout`) and per-behaviour event counts, i.e. exactly n "
        "transitions at each level (and, with ListTrace, the number of records of each kind).",
        f"- hfsm: W1 {settings.w1:,} and W2 {settings.w2:,} transitions, one a tick (`wait` of one tick, "
        f"dt 0.05, a machine `timer` ends the run), whole `run()` timed; W3 chain {settings.laps} runs of "
        f"500; trace lines W1 {settings.trace_w1:,}, W2 {settings.trace_w2:,} transitions (ListTrace keeps "
        "every record, so its figure includes the collector's passes over them and grows with n).",
        f"- Peers dispatch by name (`send`, `trigger`, `queue` + `execute_once`), sized so that a repeat "
        f"takes about {settings.budget:g} s, at most hfsm's n: {rep.sizes(pooled)}.",
        f"- W4 (`tools/bench/w4.py`): one parallel state of 4 regions, each a one-tick wait, the join "
        f"needing all four and re-entering the state; hfsm {settings.w4:,} joins, one a tick, whole "
        "`run()` timed; transitions: a `HierarchicalMachine` parallel state, `tick` then `join` when its "
        "`on_final` fired; sismic: orthogonal regions, `queue('tick')` + `execute()` (the tick, then an "
        "eventless transition guarded by `active()` of the four final states).",
        "- W3 load: hfsm `load()` of its file; transitions and the floor: PyYAML `CSafeLoader` then the "
        "build; python-statemachine `statemachine.io.load` (pure-Python SafeLoader) and instantiation; "
        "sismic `import_from_yaml` (ruamel.yaml, pure) with its validation, `Interpreter` and first "
        "`execute_once`. Each library's own schema, so the documents differ in size.",
    ]


def _calls_note() -> list[str]:
    return [
        "- Per dispatch = (calls over 2n dispatches - calls over n) / n, so one-off set-up cancels out. "
        "For hfsm a dispatch is one transition of a run, its tick loop included."
    ]


def _command(args: argparse.Namespace) -> str:
    """The command line, with the options that change what is measured."""
    words = [".venv/bin/python tools/bench_engine.py"]
    if args.quick:
        words.append("--quick")
    elif args.rounds != 3:
        words.append(f"--rounds {args.rounds}")
    if args.libs != ",".join(LIBS):
        words.append(f"--libs {args.libs}")
    return " ".join(words)


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    if args.worker:
        settings = Settings(**json.loads(args.settings)) if args.settings else Settings()
        print(json.dumps(run_worker(args.worker, settings)))
        return 0
    libs = [lib for lib in args.libs.split(",") if lib]
    unknown = sorted(set(libs) - set(LIBS))
    if unknown:
        print(f"unknown --libs {unknown}; choose from {LIBS}", file=sys.stderr)
        return 2
    settings, rounds = (QUICK, 1) if args.quick else (Settings(), args.rounds)
    begin = time.perf_counter()
    results = run_rounds(libs, rounds, settings)
    if args.json:
        args.json.write_text(json.dumps(results, indent=1), encoding="utf-8")
    pooled = {lib: rep.pool(reports) for lib, reports in results.items()}
    command = _command(args)
    body = section(pooled, settings, command, rounds, time.perf_counter() - begin)
    print(body)
    if not (args.quick or args.no_doc):
        write_section(DOC, "bench_engine", [body])
    return 1 if any(p.errors for p in pooled.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
