"""The same sweep on local processes and on a 2-worker Dask LocalCluster: identical results, both times.

    .venv/bin/python tools/bench_sweep.py                  # 12 trials: the six starts, seeds 0 and 1
    .venv/bin/python tools/bench_sweep.py --report docs/PERFORMANCE.md
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.trial import TrialSpec, run_trial_dict  # noqa: E402
from tools.docsection import write_section  # noqa: E402
from tools.paper.reference import SCENARIOS  # noqa: E402
from tools.sweep import run_sweep  # noqa: E402


def _comparable(results: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [{k: v for k, v in r.items() if k != "wall"} for r in results]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--seeds", type=int, default=2, help="seeds per starting configuration")
    p.add_argument("--report", type=Path, help="also write the numbers as a section of this Markdown file")
    args = p.parse_args(argv)
    machine = str(ROOT / "machines" / "move_furniture.yaml")
    specs = [TrialSpec(machine, name, seed) for name, _ in SCENARIOS for seed in range(args.seeds)]
    from distributed import LocalCluster

    walls: dict[str, float] = {}
    runs: dict[str, list[dict[str, Any]]] = {}
    started = time.perf_counter()
    runs["local"] = run_sweep(run_trial_dict, specs, workers=2, label="local")
    walls["local processes (2)"] = time.perf_counter() - started
    started = time.perf_counter()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                      host="127.0.0.1") as cluster:
        address = "dask://" + cluster.scheduler_address.removeprefix("tcp://")
        runs["dask"] = run_sweep(run_trial_dict, specs, executor=address, label="dask")
    walls["Dask LocalCluster (2 workers), start-up included"] = time.perf_counter() - started
    same = _comparable(runs["local"]) == _comparable(runs["dask"])
    lines = [
        f"Command: `.venv/bin/python tools/bench_sweep.py --seeds {args.seeds}` ({len(specs)} trials of "
        "machines/move_furniture.yaml, 2 cores).",
        "",
        "| executor | wall time of the sweep |",
        "|---|---|",
        *(f"| {name} | {wall:.1f} s |" for name, wall in walls.items()),
        "",
        f"Results identical, trial by trial (all but each trial's own wall time): **{same}**.",
    ]
    print("\n".join(lines))
    if args.report:
        write_section(args.report, "bench_sweep", lines)
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
