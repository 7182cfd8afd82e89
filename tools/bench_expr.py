"""Time hostile expressions: how long compiling one takes to refuse it (or accept it), in process, and
the whole `hfsm-run FILE --check` of a file holding it, in a subprocess (CPU seconds and peak
resident memory, imports included). Rewrites the bench_expr section of docs/PERFORMANCE.md.
Usage: .venv/bin/python tools/bench_expr.py [--repeats N] [--no-doc]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from hfsm.expr import ExprSyntaxError, Names, compile_expr

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
CASES = {
    "`vars.x + 1` (the baseline: start and imports)": "vars.x + 1",
    "10,000 unary minus signs": "-" * 10_000 + "1",
    "20,000 `not`s": "not " * 20_000 + "true",
    "a sum of 20,000 terms": "+".join(["1"] * 20_000),
    "a sum of 2,000 terms (4,000 characters)": "+".join(["1"] * 2_000),
    "999 unary minus signs": "-" * 999 + "1",
    "200 nested brackets": "(" * 200 + "1" + ")" * 200,
    "a 100,000-digit literal": "9" * 100_000,
    "a 1,000,000-character string": "'" + "a" * 1_000_000 + "'",
    "a list of 3,000 numbers (accepted)": "[" + ", ".join(["1"] * 3_000) + "]",
}
MEASURE = """
import json, resource, subprocess, sys
done = subprocess.run(sys.argv[1:], capture_output=True, text=True)
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = usage.ru_utime + usage.ru_stime
print(json.dumps({"code": done.returncode, "rss_kb": usage.ru_maxrss, "cpu": cpu}))
"""


def compile_ms(text: str, repeats: int) -> tuple[float, str]:
    times, outcome = [], "accepted"
    for _ in range(repeats):
        start = time.perf_counter()
        try:
            compile_expr(text, Names([], ["x"]))
        except ExprSyntaxError as exc:
            outcome = f"E314 at {exc.start}"
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times), outcome


def check_run(text: str, folder: Path) -> dict[str, float]:
    path = folder / "m.yaml"
    state = f'  s:\n    do: set\n    with: {{x: "${{{text}}}"}}\n    on: {{done: done}}\n'
    path.write_text(f"outcomes: [done]\nvars: {{x: 0}}\nstates:\n{state}")
    command = [sys.executable, "-c", MEASURE, sys.executable, "-m", "hfsm.cli.run", str(path), "--check"]
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    got: dict[str, float] = json.loads(done.stdout)
    return got


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--no-doc", action="store_true")
    args = parser.parse_args()
    lines = [
        f"Measured by `tools/bench_expr.py` on {platform.machine()}, Python {platform.python_version()}: "
        f"compiling in process (median of {args.repeats}), and `hfsm-run FILE --check` in a subprocess "
        "(CPU seconds and peak resident memory, Python's start and imports included).",
        "",
        "| expression | compile, ms | outcome | `--check` exit | CPU s | peak RSS, MB |",
        "|---|---|---|---|---|---|",
    ]
    worst_cpu = worst_rss = 0.0
    with tempfile.TemporaryDirectory() as folder:
        for name, text in CASES.items():
            ms, outcome = compile_ms(text, args.repeats)
            got = check_run(text, Path(folder))
            worst_cpu, worst_rss = max(worst_cpu, got["cpu"]), max(worst_rss, got["rss_kb"] / 1024)
            check = f"{got['code']:.0f} | {got['cpu']:.2f} | {got['rss_kb'] / 1024:.0f}"
            row = f"| {name} | {ms:.2f} | {outcome} | {check} |"
            lines.append(row)
            print(row, flush=True)
    worst = f"- worst: **{worst_cpu:.2f} CPU s**, **{worst_rss:.0f} MB**, imports included"
    lines += ["", worst + " (bound: a second and 100 MB for the check)"]
    if not args.no_doc:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_expr", lines)


if __name__ == "__main__":
    main()
