"""W1 and W2 of bench_engine on this engine and on an older one (a git revision), in the same run.

Usage: .venv/bin/python tools/bench_before.py [--rev aa98aa6] [--rounds 7] [--callgrind] [--no-doc]

The older engine is `git archive REV hfsm` unpacked into a temporary folder and put first on the
PYTHONPATH of its worker processes; both run the same workload files (tools/bench/hfsm_workloads.py).
Each round runs one fresh process per engine (order alternated); a process times W1 and W2 (best of 5
after a warm-up, `perf_counter` and `process_time`) and counts Python / C calls a transition. With
`--callgrind`, each engine also runs under `valgrind --tool=callgrind` at n and 2n transitions: the
difference of the instructions executed, over n, is a noise-free cost per transition. Rewrites the
bench_before section of docs/PERFORMANCE.md.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
TOOLS = ROOT / "tools"
if str(TOOLS) not in sys.path:
    sys.path.insert(0, str(TOOLS))

from docsection import write_section  # noqa: E402

DOC = ROOT / "docs" / "PERFORMANCE.md"
REV = "aa98aa6"  # main just before the runtime became a tree (a19a10b)
SIZES = {"w1": 100_000, "w2": 20_000}
CELLS = {"w1": ("w1", "none"), "w2": ("w2", "none"), "w1_jsonl": ("w1", "jsonl"), "w2_jsonl": ("w2", "jsonl")}
SIZES = {"w1": 100_000, "w2": 20_000, "w1_jsonl": 20_000, "w2_jsonl": 5_000}  # transitions timed
GRIND = {"w1": 2_000, "w2": 1_000, "w1_jsonl": 2_000, "w2_jsonl": 1_000}  # callgrind: n and 2n
REPEATS = 5
MARK = "time_process_time"  # callgrind dumps its counts before each call of time.process_time


def _work(cell: str, n: int, folder: Path) -> Any:
    from bench.hfsm_workloads import HfsmBench

    kind, trace = CELLS[cell]
    bench = HfsmBench(folder)
    return bench.flat(n, trace) if kind == "w1" else bench.nested(n, trace)


def worker(folder: Path) -> dict[str, Any]:
    """Time each cell and count its calls, in this process (whichever hfsm it imports)."""
    import gc

    from bench.harness import count_calls

    out: dict[str, Any] = {}
    for cell, n in SIZES.items():
        work = _work(cell, n, folder)
        handle = work.prepare(n)
        work.execute(handle)  # warm-up
        wall, cpu = [], []
        for _ in range(REPEATS):
            handle = work.prepare(n)
            gc.collect()
            begin, begin_cpu = time.perf_counter(), time.process_time()
            work.execute(handle)
            wall.append(time.perf_counter() - begin)
            cpu.append(time.process_time() - begin_cpu)
            work.check(handle, n)
        calls = count_calls(_work(cell, 1, folder), 1000, 2000)
        out[cell] = {"wall": min(wall) / n, "cpu": min(cpu) / n, "calls": [calls.python, calls.builtin]}
    out["hfsm"] = _hfsm_from()
    return out


def grind_worker(folder: Path) -> None:
    """Each cell at n and at 2n transitions, each run between two calls of time.process_time."""
    for cell, n in GRIND.items():
        for size in (n, 2 * n):
            work = _work(cell, size, folder)
            handle = work.prepare(size)
            time.process_time()
            work.execute(handle)
            time.process_time()
            work.check(handle, size)


def _hfsm_from() -> str:
    """The one folder every imported hfsm module came from (hfsm is a namespace package)."""
    folders = set()
    for name, module in list(sys.modules.items()):
        file = getattr(module, "__file__", None)
        if name.split(".")[0] == "hfsm" and file:
            depth = name.count(".") + (Path(file).name == "__init__.py")
            folders.add(str(Path(file).resolve().parents[depth]))
    if len(folders) != 1:
        raise SystemExit(f"hfsm imported from {sorted(folders)}")
    return folders.pop()


def _env(code: Path) -> dict[str, str]:
    return dict(os.environ, PYTHONPATH=f"{code}{os.pathsep}{TOOLS}", PYTHONHASHSEED="0")


def spawn(code: Path, *args: str) -> dict[str, Any]:
    command = [sys.executable, str(Path(__file__).resolve()), "--worker", *args]
    done = subprocess.run(command, capture_output=True, text=True, env=_env(code), check=False)
    if done.returncode != 0:
        raise SystemExit(f"worker on {code} failed:\n{done.stderr}")
    result: dict[str, Any] = json.loads(done.stdout.strip().splitlines()[-1])
    return result


def instructions(code: Path) -> dict[str, float]:
    """Instructions a transition of each cell, from one callgrind run of `grind_worker`."""
    with tempfile.TemporaryDirectory(prefix="bench_before_grind_") as folder:
        out = Path(folder) / "cg.out"
        command = ["valgrind", "--tool=callgrind", f"--dump-before={MARK}", f"--callgrind-out-file={out}"]
        command += [sys.executable, str(Path(__file__).resolve()), "--worker", "--grind"]
        done = subprocess.run(command, capture_output=True, text=True, env=_env(code), check=False)
        if done.returncode != 0:
            raise SystemExit(f"callgrind on {code} failed:\n{done.stderr[-2000:]}")
        dumps = {int(p.suffix[1:]): p for p in Path(folder).glob("cg.out.*")}
        total = {j: int(re.search(r"^totals: (\d+)", p.read_text(), re.M).group(1)) for j, p in dumps.items()}  # type: ignore[union-attr]
    # the dump before the process_time call that ends a run holds the run: calls 2, 4, 6, ...
    got = {}
    for i, (cell, n) in enumerate(GRIND.items()):
        got[cell] = (total[4 * i + 4] - total[4 * i + 2]) / n
    return got


def _git(*args: str) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, check=True)


def checkout(rev: str, into: Path) -> Path:
    """The package hfsm as it was at `rev`, unpacked into `into`."""
    subprocess.run(["tar", "-x", "-C", str(into)], input=_git("archive", rev, "hfsm").stdout, check=True)
    return into


def _head() -> str:
    dirty = _git("status", "--porcelain", "--", "hfsm").stdout.strip()
    head = _git("log", "-1", "--format=%h").stdout.decode().strip()
    return head + (" + uncommitted changes" if dirty else "")


Runs = dict[str, list[dict[str, Any]]]


def measure(codes: dict[str, Path], rounds: int) -> Runs:
    runs: Runs = {name: [] for name in codes}
    names = list(codes)
    for r in range(rounds):
        for name in names if r % 2 == 0 else names[::-1]:
            runs[name].append(spawn(codes[name]))
            got = runs[name][-1]
            print(
                f"round {r + 1}/{rounds} {name}: W1 {got['w1']['wall'] * 1e6:.2f} µs, "
                f"W2 {got['w2']['wall'] * 1e6:.2f} µs",
                file=sys.stderr,
            )
    return runs


def _median(runs: list[dict[str, Any]], kind: str, clock: str) -> float:
    return float(statistics.median(r[kind][clock] for r in runs))


def _paired(runs: Runs, kind: str, clock: str) -> float:
    """Median over rounds of now / before, each round's pair measured back to back."""
    pairs = zip(runs["now"], runs["before"], strict=True)
    return float(statistics.median(n[kind][clock] / b[kind][clock] for n, b in pairs))


def section(runs: Runs, grind: dict[str, dict[str, float]], rev: str, rounds: int) -> list[str]:
    us: Callable[[float], str] = lambda s: f"{s * 1e6:.2f}"  # noqa: E731
    lines = [
        "## This engine against the one before the tree (bench_before)",
        "",
        f"Measured by `tools/bench_before.py` on {platform.machine()}, {os.cpu_count()} CPUs, Python "
        f"{platform.python_version()}, {time.strftime('%Y-%m-%d')}; now: {_head()}, before: `{rev}` "
        "(main just before the runtime became a tree). Load average at the end: "
        f"{os.getloadavg()[0]:.1f} (shared 2-core VM).",
        f"Command: `.venv/bin/python tools/bench_before.py{' --callgrind' if grind else ''}` ({rounds} "
        "rounds; each round one fresh process per engine, order alternated; a figure is the median over "
        f"rounds of the best of {REPEATS} repeats; W1 {SIZES['w1']:,} and W2 {SIZES['w2']:,} transitions, "
        "the workloads of bench_engine).",
        "",
    ]
    head = ["", "W1 µs/transition (wall)", "W1 CPU", "W2 µs/transition (wall)", "W2 CPU"]
    head += ["Python / C calls a transition, W1", "W2"]
    head += ["instructions a transition (callgrind), W1", "W2"] if grind else []
    rows = []
    for name in ("before", "now"):
        got = runs[name]
        cells = [_label(name, rev)]
        for kind in ("w1", "w2"):
            cells += [us(_median(got, kind, "wall")), us(_median(got, kind, "cpu"))]
        cells += ["{:.0f} / {:.0f}".format(*got[0][kind]["calls"]) for kind in ("w1", "w2")]
        cells += [f"{grind[name][kind]:,.0f}" for kind in ("w1", "w2")] if grind else []
        rows.append(cells)
    ratios = ["now / before, median of the rounds' pairs"]
    for kind in ("w1", "w2"):
        ratios += [f"{_paired(runs, kind, 'wall'):.2f}x", f"{_paired(runs, kind, 'cpu'):.2f}x"]
    ratios += ["", ""]
    if grind:
        ratios += [f"{grind['now'][kind] / grind['before'][kind]:.2f}x" for kind in ("w1", "w2")]
    lines += _table(head, [*rows, ratios])
    lines += ["", *_trace_table(runs, grind, rev)]
    if grind:
        lines += [
            "",
            "- Instructions: `valgrind --tool=callgrind` of one worker process per engine that runs each "
            "workload at n and 2n transitions between calls of `time.process_time` (callgrind "
            f"`--dump-before={MARK}`); (I(2n) - I(n)) / n, so a run's set-up cancels out (W1 n = "
            f"{GRIND['w1']:,}, W2 n = {GRIND['w2']:,}, PYTHONHASHSEED=0): the same on every run.",
        ]
    return lines


def _trace_table(runs: Runs, grind: dict[str, dict[str, float]], rev: str) -> list[str]:
    """The JSONL trace (to /dev/null) on against off, in the same process: issue 12's point 6."""
    head = ["", "W1 on µs/transition (wall)", "W1 on / off (wall)", "W1 on / off (CPU)"]
    head += ["W2 on µs/transition", "W2 on / off (wall)", "W2 on / off (CPU)"]
    head += ["W1 on / off (instructions)", "W2"] if grind else []
    rows = []
    for name in ("before", "now"):
        got = runs[name]
        cells = [_label(name, rev)]
        for kind in ("w1", "w2"):
            cells.append(f"{_median(got, kind + '_jsonl', 'wall') * 1e6:.2f}")
            for clock in ("wall", "cpu"):
                ratio = statistics.median(r[kind + "_jsonl"][clock] / r[kind][clock] for r in got)
                cells.append(f"{ratio:.2f}x")
        cells += [f"{grind[name][k + '_jsonl'] / grind[name][k]:.2f}x" for k in ("w1", "w2")] if grind else []
        rows.append(cells)
    intro = (
        f"The JSONL trace on (`JsonlTrace` to /dev/null; W1 {SIZES['w1_jsonl']:,} and W2 "
        f"{SIZES['w2_jsonl']:,} transitions) against off, timed in the same worker processes (on / off: "
        "median of the rounds' ratios):"
    )
    return [intro, "", *_table(head, rows)]


def _label(name: str, rev: str) -> str:
    return "now" if name == "now" else f"before (`{rev}`)"


def _table(head: list[str], rows: list[list[str]]) -> list[str]:
    """A Markdown table, the first column text and the others figures (right-aligned)."""
    rule = "|---" + "|---:" * (len(head) - 1) + "|"
    return ["| " + " | ".join(head) + " |", rule, *("| " + " | ".join(r) + " |" for r in rows)]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rev", default=REV, help="the older engine's git revision")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--callgrind", action="store_true", help="also count instructions with callgrind")
    parser.add_argument("--no-doc", action="store_true", help="print only; leave PERFORMANCE.md")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--grind", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        with tempfile.TemporaryDirectory(prefix="bench_before_") as folder:
            if args.grind:
                grind_worker(Path(folder))
            else:
                print(json.dumps(worker(Path(folder))))
        return 0
    with tempfile.TemporaryDirectory(prefix="bench_before_code_") as folder:
        codes = {"before": checkout(args.rev, Path(folder)), "now": ROOT}
        grind: dict[str, dict[str, float]] = {}
        if args.callgrind:
            grind = {name: instructions(code) for name, code in codes.items()}
            print(f"callgrind instructions a transition: {grind}", file=sys.stderr)
        runs = measure(codes, args.rounds)
        for name, code in codes.items():
            expect_from = str(code.resolve())
            if runs[name][0]["hfsm"] != expect_from:
                raise SystemExit(f"{name} imported {runs[name][0]['hfsm']}, not {expect_from}")
    lines = section(runs, grind, args.rev, args.rounds)
    print("\n".join(lines))
    if not args.no_doc:
        write_section(DOC, "bench_before", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
