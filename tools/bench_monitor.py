"""What `--monitor` costs a whole simulated trial: wall time with and without it, and the trace bytes.

    .venv/bin/python tools/bench_monitor.py --report docs/PERFORMANCE.md
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tools.docsection import write_section  # noqa: E402

HFSM_RUN = str(Path(sys.executable).parent / "hfsm-run")


def trial(out: Path, monitor: bool) -> float:
    command = [HFSM_RUN, str(ROOT / "machines" / "move_furniture.yaml"), "--seed", "3", "--out", str(out),
               "--no-video", "--quiet", "--progress", "0"]
    if monitor:
        command += ["--monitor", "--monitor-hold", "0"]
    begin = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - begin


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", type=int, default=5, help="pairs of runs, alternated")
    p.add_argument("--report", type=Path)
    args = p.parse_args(argv)
    out = ROOT / "out" / "bench_monitor"
    walls: dict[bool, list[float]] = {False: [], True: []}
    traces: dict[bool, bytes] = {}
    for _ in range(args.runs):
        for monitor in (False, True):
            folder = out / ("with" if monitor else "without")
            walls[monitor].append(trial(folder, monitor))
            traces[monitor] = (folder / "opposite_long_side-seed3.jsonl").read_bytes()
    ratios = [w / o for w, o in zip(walls[True], walls[False], strict=True)]
    lines = [
        f"Command: `.venv/bin/python tools/bench_monitor.py --runs {args.runs}`",
        "(machines/move_furniture.yaml, seed 3, no video; runs with and without `--monitor` alternated;",
        "medians).",
        "",
        "| | wall time of the trial |",
        "|---|---|",
        f"| without `--monitor` | {statistics.median(walls[False]):.2f} s |",
        f"| with `--monitor` (page served, no browser attached) | {statistics.median(walls[True]):.2f} s |",
        "",
        f"Ratio with/without, median of pairs: **{statistics.median(ratios):.2f}**. Same trace bytes: "
        f"**{traces[True] == traces[False]}** ({len(traces[False])} bytes).",
    ]
    print("\n".join(lines))
    if args.report:
        write_section(args.report, "bench_monitor", lines)
    return 0 if traces[True] == traces[False] else 1


if __name__ == "__main__":
    sys.exit(main())
