"""hfsm-verify on one process and on several (`--workers`), side by side: the same searches run in
turn, each a process of its own, and the wall time of the search, its CPU time (the workers'
included) and the states it explored.

Rewrites the bench_verify_workers section of docs/VERIFY.md (nothing else in it).
Usage: nice -n 15 .venv/bin/python tools/bench_verify_workers.py [--no-doc] [--runs N] [--workers N]
       [--max-states N]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
M = ROOT / "machines"
PAIR = ["--agents", "r1,r2"]


def cases(max_states: int) -> list[tuple[str, list[str]]]:
    return [
        ("call_off, --loss 1 --fail 1",
         [str(M / "call_off.yaml"), *PAIR, "--param", "cycle=1", "--loss", "1", "--fail", "1"]),
        (f"move_furniture, --loss 1 --fail 1, its first {max_states:,} states",
         [str(M / "move_furniture.yaml"), *PAIR, "--loss", "1", "--fail", "1",
          "--max-states", str(max_states)]),
    ]  # fmt: skip


def one(args: list[str], workers: int) -> dict[str, Any]:
    """One search in a process of its own: its verdict, and the CPU-seconds of it and its workers."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryDirectory() as folder:
        done = subprocess.run(
            [sys.executable, "-m", "hfsm.cli.verify", *args, "--workers", str(workers), "--json",
             "--out", str(Path(folder) / "ce.jsonl")],
            capture_output=True, text=True, check=False,
        )  # fmt: skip
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode not in (0, 1):
        raise SystemExit(f"hfsm-verify failed:\n{done.stderr}")
    verdict: dict[str, Any] = json.loads(done.stdout)
    verdict["cpu"] = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    return verdict


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-doc", action="store_true", help="print only; leave docs/VERIFY.md")
    parser.add_argument("--runs", type=int, default=3, help="runs of each case and each count (medians)")
    parser.add_argument("--workers", type=int, default=2, help="the workers compared with one process")
    parser.add_argument("--max-states", type=int, default=20_000, help="move_furniture's states")
    args = parser.parse_args()
    rows = []
    for name, case in cases(args.max_states):
        alone: list[dict[str, Any]] = []
        many: list[dict[str, Any]] = []
        for _ in range(args.runs):  # in turn, so that both see the same load
            alone.append(one(case, 1))
            many.append(one(case, args.workers))
        ratios = [a["seconds"] / m["seconds"] for a, m in zip(alone, many, strict=True)]
        for label, runs in (("1", alone), (str(args.workers), many)):
            spent = statistics.median(r["seconds"] for r in runs)
            cpu = statistics.median(r["cpu"] for r in runs)
            rows.append(
                f"| {name} | {label} | {runs[0]['verdict']} | {runs[0]['states']:,} | {spent:.1f} "
                f"| {runs[0]['states'] / spent:,.0f} | {cpu:.1f} |"
            )
            print(rows[-1], flush=True)
        speedup = statistics.median(ratios)
        rows.append(f"| | speed-up (median of {args.runs} pairs) | | | **{speedup:.2f}** | | |")
        print(rows[-1], flush=True)
    load = os.getloadavg()[0]
    lines = [
        "",
        f"`nice -n 15 .venv/bin/python tools/bench_verify_workers.py --runs {args.runs} "
        f"--workers {args.workers} --max-states {args.max_states}` on {platform.python_implementation()} "
        f"{platform.python_version()}, {os.cpu_count()} cores, load average {load:.1f} when it ended:",
        "",
        "| case | workers | verdict | states | seconds of search (median) | states/s | CPU-s of the "
        "process and its workers (median) |",
        "|---|---|---|---|---|---|---|",
        *rows,
        "",
    ]
    if not args.no_doc:
        write_section(ROOT / "docs" / "VERIFY.md", "bench_verify_workers", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
