"""Time `hfsm-graph` drawing every machine of machines/ (and examples/), in process.

Rewrites the bench_graph section of docs/PERFORMANCE.md (nothing else in that shared file); the last
line printed is the headline: seconds to draw all of machines/ as SVG (target: under 2 s).
Usage: .venv/bin/python tools/bench_graph.py [--repeats N] [--no-doc]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from hfsm.cli.graph import build_parser, draw, machine_files

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
TARGET_S = 2.0
FOLDERS = ("machines", "examples", "tests/diagram/data")


def seconds_to_draw(folder: Path, fmt: str, repeats: int, depth: int = 0) -> float:
    """Median wall time of one whole `hfsm-graph FOLDER --format FMT` (load, check, lay out, draw)."""
    args = build_parser().parse_args([str(folder), "--format", fmt, "--depth", str(depth)])
    times = []
    for _ in range(repeats):
        begin = time.perf_counter()
        draw(args)
        times.append(time.perf_counter() - begin)
    return statistics.median(times)


def cold_cli_seconds(folder: Path, repeats: int) -> float:
    """Median wall time of the console script in a fresh process (imports included), writing SVG."""
    script = Path(sys.executable).parent / "hfsm-graph"
    times = []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as out:
            begin = time.perf_counter()
            subprocess.run([str(script), str(folder), "-o", out], check=True, capture_output=True)
            times.append(time.perf_counter() - begin)
    return statistics.median(times)


def rows(repeats: int) -> list[tuple[str, int, str, float]]:
    out = []
    for name in FOLDERS:
        folder = ROOT / name
        count = len(machine_files([folder])) if folder.is_dir() else 0
        if not count:
            continue
        for fmt, depth in (("dot", 0), ("svg", 0), ("png", 0), ("svg", 2)):
            shown = f"{fmt}, --depth {depth}" if depth else fmt
            out.append((name, count, shown, seconds_to_draw(folder, fmt, repeats, depth)))
        out.append((name, count, "svg, cold `hfsm-graph` process", cold_cli_seconds(folder, repeats)))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="runs per row; the median is kept")
    parser.add_argument("--no-doc", action="store_true", help="do not touch PERFORMANCE.md")
    args = parser.parse_args()
    table = rows(args.repeats)
    lines = [
        f"Measured by `tools/bench_graph.py` on {platform.machine()}, {os.cpu_count()} CPUs, "
        f"Python {platform.python_version()}: one whole `hfsm-graph FOLDER --format F` in process "
        f"(load and check, figures, call graph, legend, Graphviz layout), median of {args.repeats}.",
        "",
        "| folder | machines | format | total s | ms per machine |",
        "|---|---|---|---|---|",
    ]
    lines += [f"| {f} | {n} | {fmt} | {s:.3f} | {1000 * s / n:.0f} |" for f, n, fmt, s in table]
    headline = next((s for f, _, fmt, s in table if f == "machines" and fmt.startswith("svg, cold")), None)
    verdict = (
        f"all of machines/ as SVG, `hfsm-graph machines` from a cold start: **{headline:.2f} s** "
        f"(target < {TARGET_S:g} s)"
        if headline is not None
        else "machines/ holds no machine yet"
    )
    lines += ["", f"- {verdict}"]
    print("\n".join(lines))
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_graph", lines)
    print(verdict)


if __name__ == "__main__":
    main()
