"""TARARC's experiments (the paper's section 5) with machines/tararc.yaml in the pybullet world.

    nice -n 10 .venv/bin/python tools/tararc_bench.py           # the whole bench, docs/TARARC.md
    .venv/bin/python tools/tararc_bench.py --quick              # a smoke run (fewer points, 1 seed)
    .venv/bin/python tools/tararc_bench.py --from docs/results/tararc.json   # the docs again, no run
    tools/tararc_bench.py --shard 1/2 & tools/tararc_bench.py --shard 2/2   # the first stage in parts
    tools/tararc_bench.py --merge          # the parts read back, the help trials run, the docs
    tools/tararc_bench.py --only ability   # Figure 8 run again, the rest read from --raw, the docs

Table 1 (the six priority orders of 3 tasks), Figure 5 (robot density), Figure 6 (10 to 50
robots), Figure 7 (robot speed), Figure 8 (4 allocations sharing a history file) and the help
strategies (every robot of 10 failing once mid-move). Each trial generates its scenario into a
temporary folder and runs seeded; trials run in parallel processes (or on a Dask cluster) through
tools/sweep.py, and results come back sorted by trial, the same on any number of workers. The help
trials fail each robot at a time read off the failure-free run of the same seed, so they run
after the others: shards (`--shard I/N`, as tools/sweep.py makes them) split the first stage, and
`--merge` reads them back, runs the help trials and writes the docs.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tools.docsection import write_section  # noqa: E402
from tools.sweep import (  # noqa: E402
    Shard,
    SweepError,
    add_executor_args,
    add_results_args,
    merge_shards,
    run_sweep,
    save_results,
    shard_path,
    write_shard,
)
from tools.tararc.experiments import EXPERIMENTS, QUICK, Config, help_trials, main_trials  # noqa: E402
from tools.tararc.report import write  # noqa: E402
from tools.tararc.trials import BenchTrial, run_bench_trial  # noqa: E402

LABEL = "tararc"


def first_stage(config: Config, executor: str = "local", workers: int = 2, shard: Shard | None = None,
                shards: Path | None = None, merge: bool = False) -> list[dict[str, Any]] | None:
    """Table 1 and Figures 5-8: run (all, or one shard written to `shards`: then None), or with
    `merge` read back from the shards in `shards`."""
    trials = main_trials(config)
    if merge:
        paths = sorted((shards or Path()).glob(f"{LABEL}-*-of-*.jsonl"))
        if not paths:
            raise SweepError(f"no shards of '{LABEL}' in {shards}")
        return merge_shards(paths)
    part = run_sweep(run_bench_trial, trials, executor=executor, workers=workers, shard=shard, label=LABEL)
    if shard is None:
        return part
    write_shard(shard_path(shards or Path(), LABEL, shard), part, len(trials))
    return None


def run_bench(config: Config, executor: str = "local", workers: int = 2,
              first: list[dict[str, Any]] | None = None) -> list[dict[str, Any]]:
    """Every trial's result (wall seconds aside, the same whatever the executor, workers or shards);
    `first`: the first stage's results, already run."""
    results = first if first is not None else first_stage(config, executor, workers) or []
    second: list[BenchTrial] = help_trials(config, results)
    helped = run_sweep(run_bench_trial, second, executor=executor, workers=workers, label="tararc-help")
    return results + [{**r, "trial": r["trial"] + len(results)} for r in helped]


def rerun(config: Config, only: list[str], saved: dict[str, Any], executor: str = "local",
          workers: int = 2) -> list[dict[str, Any]]:
    """The saved results with the first-stage experiments `only` run again in their place (the help
    trials, which need Table 1's, cannot be chosen), renumbered in order."""
    if not only or "help" in only or not set(only) <= set(EXPERIMENTS):
        raise SweepError(f"--only takes experiments among {', '.join(e for e in EXPERIMENTS if e != 'help')}")
    new = run_sweep(run_bench_trial, [t for t in main_trials(config) if t.experiment in only],
                    executor=executor, workers=workers, label=LABEL)
    old = saved["results"]
    at = next((i for i, r in enumerate(old) if r["experiment"] in [*only, "help"]), len(old))
    kept = [r for r in old if r["experiment"] not in only]
    merged = kept[:at] + new + kept[at:]
    return [{**r, "trial": i} for i, r in enumerate(merged)]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true", help="a smoke run: few points, one seed")
    p.add_argument("--seeds", type=int, help="seeds per point of Table 1 and Figures 5 and 7")
    p.add_argument("--sizes", help="team sizes of Figure 6, comma-separated (default 10,20,30,40,50)")
    p.add_argument("--first-seed", type=int, default=1)
    add_executor_args(p)
    add_results_args(p, "tararc", "TARARC.md")
    p.add_argument("--perf", type=Path, default=ROOT / "docs" / "PERFORMANCE.md",
                   help="where the bench's wall time is also written")
    p.add_argument("--shard", type=Shard.parse, help="run shard I of N (I/N) of the first stage, to --shards")
    p.add_argument("--merge", action="store_true", help="read the first stage from --shards, run the rest")
    p.add_argument("--only", type=lambda text: text.split(","), metavar="EXP[,EXP]",
                   help=f"run only these experiments ({', '.join(EXPERIMENTS[:-1])}) again; the rest "
                   "from --raw")
    p.add_argument("--shards", type=Path, default=ROOT / "out" / "shards", help="folder of shard files")
    args = p.parse_args(argv)
    config = replace(QUICK if args.quick else Config(), first_seed=args.first_seed)
    if args.seeds:
        config = replace(config, seeds=args.seeds)
    if args.sizes:
        config = replace(config, sizes=tuple(int(n) for n in args.sizes.split(",")))
    command = " ".join(["tools/tararc_bench.py", *(argv if argv is not None else sys.argv[1:])])
    if args.saved:
        saved = json.loads(args.saved.read_text(encoding="utf-8"))
    elif args.only:
        started = time.perf_counter()
        try:
            if not args.raw.exists():
                raise SweepError(f"--only runs some experiments again: the others come from {args.raw}, "
                                 "which does not exist (run the whole bench first)")
            saved = json.loads(args.raw.read_text(encoding="utf-8"))
            saved["results"] = rerun(config, args.only, saved, args.executor, args.workers)
        except SweepError as exc:
            print(f"tararc_bench: {exc}", file=sys.stderr)
            return 2
        trials = sum(r["experiment"] in args.only for r in saved["results"])
        saved.setdefault("reruns", []).append(
            {"command": command, "trials": trials, "wall": round(time.perf_counter() - started, 1)})
        save_results(args.raw, saved)
    else:
        started = time.perf_counter()
        try:
            first = first_stage(config, args.executor, args.workers, args.shard, args.shards, args.merge)
            if first is None:
                print(f"wrote shard {args.shard.index}/{args.shard.count} to {args.shards}", file=sys.stderr)
                return 0
            results = run_bench(config, args.executor, args.workers, first)
            if args.merge:  # the first stage ran elsewhere: its time as if it had run here
                started -= sum(r["wall"] for r in first) / args.workers
        except SweepError as exc:
            print(f"tararc_bench: {exc}", file=sys.stderr)
            return 2
        saved = {"command": command, "wall": time.perf_counter() - started, "workers": args.workers,
                 "results": results}
        save_results(args.raw, saved)
    command, wall, results = saved["command"], saved["wall"], saved["results"]
    lines = write(results, args.doc, args.figures, command, wall, len(results), saved.get("reruns", []))
    if not saved.get("reruns"):  # the whole bench's wall time, not a part's
        write_section(args.perf, "tararc_bench", [
            f"`{command}`: {len(results)} trials of machines/tararc.yaml (10 to 50 light robots) in "
            f"{wall / 60:.1f} min wall with {saved['workers']} worker processes on the "
            "shared 2-core machine (target: under 20 minutes on 2 cores); results in docs/TARARC.md."])
    print("\n".join(lines))
    print(f"wrote {args.doc} and {args.figures} ({wall / 60:.1f} min)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
