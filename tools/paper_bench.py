"""Reproduce the paper's Figure 10 and Figure 11: seeded trials of the six starting configurations.

    .venv/bin/python tools/paper_bench.py --trials 10            # 60 trials, writes docs/RESULTS.md
    .venv/bin/python tools/paper_bench.py --trials 2 --quick     # a smoke run

Trials run in parallel processes (spawn), each a full simulated run of machines/move_furniture.yaml
on a scenario and seed; the ablations rerun the same seeds with other top-level params.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.trial import TrialSpec, run_trial_dict  # noqa: E402
from tools.paper.reference import SCENARIOS  # noqa: E402
from tools.paper.report import write_report  # noqa: E402
from tools.sweep import Shard, SweepError, add_executor_args, merge_shards, run_sweep, shard_path, write_shard  # noqa: E402

ABLATIONS = {"no_wait": {"waits": False}, "margin_5": {"margin": 0.05}}


def run_all(specs: list[TrialSpec], args: argparse.Namespace, label: str) -> list[dict[str, Any]]:
    """The trials of one campaign on the chosen executor, sorted for the report."""
    results = run_sweep(run_trial_dict, specs, executor=args.executor, workers=args.workers, label=label)
    return sorted(results, key=lambda r: (r["spec"]["scenario"], r["spec"]["seed"]))


def add_sweep_args(p: argparse.ArgumentParser) -> None:
    """The options every campaign of tools/ shares: where trials run, and shards for batch queues."""
    add_executor_args(p)
    p.add_argument("--shard", type=Shard.parse, help="run only shard I of N (I/N) and write it to --shards")
    p.add_argument("--merge", action="store_true", help="write the report from the shards in --shards")
    p.add_argument("--shards", type=Path, default=ROOT / "out" / "shards", help="folder of shard files")
    p.add_argument("--radio-loss", type=float, default=0.0, metavar="P", help="chance a message is lost")
    p.add_argument("--radio-latency", type=float, default=0.1, metavar="S", help="seconds a message takes")


def radio(args: argparse.Namespace) -> dict[str, float]:
    """The TrialSpec fields of --radio-loss and --radio-latency."""
    return {"radio_loss": args.radio_loss, "radio_latency": args.radio_latency}


def campaign(specs: list[TrialSpec], args: argparse.Namespace, label: str) -> list[dict[str, Any]] | None:
    """Run (or, with --shard, run part of and store; with --merge, read back) one campaign."""
    if args.merge:
        shards = sorted(args.shards.glob(f"{label}-*-of-*.jsonl"))
        if not shards:
            raise SweepError(f"no shards of '{label}' in {args.shards}")
        results = merge_shards(shards)
        return sorted(results, key=lambda r: (r["spec"]["scenario"], r["spec"]["seed"]))
    if args.shard is not None:
        part = run_sweep(run_trial_dict, specs, executor=args.executor, workers=args.workers,
                         shard=args.shard, label=label)
        write_shard(shard_path(args.shards, label, args.shard), part, len(specs))
        return None
    return run_all(specs, args, label)


def specs_for(args: argparse.Namespace, params: dict[str, Any]) -> list[TrialSpec]:
    scenarios = [s for s, _ in SCENARIOS] if args.scenarios == "all" else args.scenarios.split(",")
    return [
        TrialSpec(str(args.machine), scenario, seed, params, args.max_time, **radio(args))
        for scenario in scenarios
        for seed in range(args.seed, args.seed + args.trials)
    ]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--trials", type=int, default=10, help="seeded trials per configuration")
    p.add_argument("--seed", type=int, default=0, help="first seed")
    add_sweep_args(p)
    p.add_argument("--scenarios", default="all", help="comma-separated names, or all")
    p.add_argument("--machine", type=Path, default=ROOT / "machines" / "move_furniture.yaml")
    p.add_argument("--max-time", type=float, default=2400.0, help="simulated seconds per trial")
    p.add_argument("--no-ablations", action="store_true")
    p.add_argument("--out", type=Path, default=ROOT / "docs" / "RESULTS.md")
    p.add_argument("--raw", type=Path, default=ROOT / "docs" / "results" / "trials.json")
    args = p.parse_args(argv)
    started = time.perf_counter()
    campaigns = {"baseline": {}, **({} if args.no_ablations else ABLATIONS)}
    try:
        runs = {name: campaign(specs_for(args, params), args, name) for name, params in campaigns.items()}
    except SweepError as exc:
        print(f"paper_bench: {exc}", file=sys.stderr)
        return 2
    if args.shard is not None:
        print(f"wrote shard {args.shard.index}/{args.shard.count} to {args.shards}", file=sys.stderr)
        return 0
    args.raw.parent.mkdir(parents=True, exist_ok=True)
    args.raw.write_text(json.dumps(runs, indent=1, default=str))
    command = " ".join(["tools/paper_bench.py", *(argv or sys.argv[1:])])
    write_report(runs, args.out, args.raw, command=command, wall=time.perf_counter() - started)
    print(f"wrote {args.out} and {args.raw}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
