"""Reproduce the paper's Figure 10 and Figure 11: seeded trials of the six starting configurations.

    .venv/bin/python tools/paper_bench.py --trials 10            # 60 trials, writes docs/RESULTS.md
    .venv/bin/python tools/paper_bench.py --trials 2 --quick     # a smoke run

Trials run in parallel processes (spawn), each a full simulated run of machines/move_furniture.yaml
on a scenario and seed; the ablations rerun the same seeds with other top-level params.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from behaviours.trial import TrialSpec, run_trial  # noqa: E402
from tools.paper.reference import SCENARIOS  # noqa: E402
from tools.paper.report import write_report  # noqa: E402

ABLATIONS = {"no_wait": {"waits": False}, "margin_5": {"margin": 0.05}}


def _one(spec: TrialSpec) -> dict[str, Any]:
    from hfsm.cli.quiet import stdout_to_stderr

    with stdout_to_stderr():
        return run_trial(spec).as_dict()


def run_all(specs: list[TrialSpec], workers: int, label: str) -> list[dict[str, Any]]:
    results: list[dict[str, Any]] = []
    started = time.perf_counter()
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        futures = [pool.submit(_one, spec) for spec in specs]
        for future in as_completed(futures):
            results.append(future.result())
            _progress(label, len(results), len(specs), time.perf_counter() - started)
    print(file=sys.stderr)
    return sorted(results, key=lambda r: (r["spec"]["scenario"], r["spec"]["seed"]))


def _progress(label: str, done: int, total: int, elapsed: float) -> None:
    width = 30
    filled = width * done // total
    bar = "#" * filled + "-" * (width - filled)
    end = "\r" if sys.stderr.isatty() else "\n"
    print(f"{label:>10} [{bar}] {done}/{total} trials, {elapsed:.0f} s", end=end, file=sys.stderr, flush=True)


def specs_for(args: argparse.Namespace, params: dict[str, Any]) -> list[TrialSpec]:
    scenarios = [s for s, _ in SCENARIOS] if args.scenarios == "all" else args.scenarios.split(",")
    return [
        TrialSpec(str(args.machine), scenario, seed, params, args.max_time)
        for scenario in scenarios
        for seed in range(args.seed, args.seed + args.trials)
    ]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--trials", type=int, default=10, help="seeded trials per configuration")
    p.add_argument("--seed", type=int, default=0, help="first seed")
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--scenarios", default="all", help="comma-separated names, or all")
    p.add_argument("--machine", type=Path, default=ROOT / "machines" / "move_furniture.yaml")
    p.add_argument("--max-time", type=float, default=2400.0, help="simulated seconds per trial")
    p.add_argument("--no-ablations", action="store_true")
    p.add_argument("--out", type=Path, default=ROOT / "docs" / "RESULTS.md")
    p.add_argument("--raw", type=Path, default=ROOT / "docs" / "results" / "trials.json")
    args = p.parse_args(argv)
    started = time.perf_counter()
    runs = {"baseline": run_all(specs_for(args, {}), args.workers, "baseline")}
    if not args.no_ablations:
        for name, params in ABLATIONS.items():
            runs[name] = run_all(specs_for(args, params), args.workers, name)
    args.raw.parent.mkdir(parents=True, exist_ok=True)
    args.raw.write_text(json.dumps(runs, indent=1, default=str))
    command = " ".join(["tools/paper_bench.py", *(argv or sys.argv[1:])])
    write_report(runs, args.out, args.raw, command=command, wall=time.perf_counter() - started)
    print(f"wrote {args.out} and {args.raw}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
