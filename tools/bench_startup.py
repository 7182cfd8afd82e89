"""Start-up of the world-free commands, each a whole process: `--check`, `--list`, `hfsm-graph`.

Each command runs `--runs` times after a warm-up; the figure is the median CPU seconds (user + sys,
from the kernel's accounting of the finished child) and the median wall seconds; `python -c pass`
is the floor. Rewrites the bench_startup section of docs/PERFORMANCE.md (unless --no-doc).
Usage: .venv/bin/python tools/bench_startup.py [--runs N] [--no-doc]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
TARGET_S = 0.3


def commands(out: str) -> dict[str, list[str]]:
    py = sys.executable
    return {
        "python -c pass (the floor)": [py, "-c", "pass"],
        "hfsm-run examples/hello.yaml --check": [py, "-m", "hfsm.cli.run", "examples/hello.yaml", "--check"],
        "hfsm-run machines/move_furniture.yaml --check": [
            py, "-m", "hfsm.cli.run", "machines/move_furniture.yaml", "--check",
        ],
        "hfsm-run --list": [py, "-m", "hfsm.cli.run", "--list"],
        "hfsm-graph machines/move_table.yaml --format dot": [
            py, "-m", "hfsm.cli.graph", "machines/move_table.yaml", "-o", out, "--format", "dot",
        ],
    }  # fmt: skip


def measure(argv: list[str], runs: int) -> tuple[float, float]:
    """Median (cpu, wall) seconds of `argv` run as a child process."""
    cpu, wall = [], []
    for i in range(runs + 1):
        before = os.times()
        begin = time.perf_counter()
        subprocess.run(argv, cwd=ROOT, capture_output=True, check=True)
        end = time.perf_counter()
        after = os.times()
        if i:  # the first run warms the file cache
            used = after.children_user + after.children_system
            cpu.append(used - before.children_user - before.children_system)
            wall.append(end - begin)
    return statistics.median(cpu), statistics.median(wall)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("--no-doc", action="store_true")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for name, argv in commands(out).items():
            cpu, wall = measure(argv, args.runs)
            rows.append(f"| `{name}` | {cpu:.3f} | {wall:.3f} |")
            print(rows[-1], flush=True)
    lines = [
        "## Start-up of the world-free commands (`.venv/bin/python tools/bench_startup.py`)",
        "",
        f"Median of {args.runs} whole processes after a warm-up; CPU is user + sys of the child. Target: "
        f"`--check` of a small machine under {TARGET_S} s. None of these imports pybullet, OpenCV or "
        "numpy (tests/cli/test_startup.py).",
        "",
        "| command | CPU s | wall s |",
        "|---|---:|---:|",
        *rows,
    ]
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_startup", lines)


if __name__ == "__main__":
    main()
