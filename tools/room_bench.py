"""Clear any room (issue 20): a seeded campaign of machines/clear_room.yaml in rooms drawn by the
generator (hfsm_sim.roomgen), the same number in each stratum.

    nice -n 15 .venv/bin/python tools/room_bench.py                  # 25 rooms per stratum, held seeds
    .venv/bin/python tools/room_bench.py --quick                     # a smoke run (2 rooms, 20 sim s)
    .venv/bin/python tools/room_bench.py --rooms 3 --first-seed 1    # development seeds
    tools/room_bench.py --shard 1/4 --shards out/room &  ...         # a part of it; then --merge
    .venv/bin/python tools/room_bench.py --from docs/results/room.json   # the docs again, no run

Seeds 1-99 are for development; the measure starts at seed 10000 (`--first-seed`, default), seeds
never looked at while developing. `--trials 0,40,72` runs only those trials of the campaign (numbered
as in the whole). Each trial writes its room into a temporary folder and runs it headless through
the run API hfsm-run uses; trials run in parallel processes (or on a Dask cluster) through
tools/sweep.py, and results come back sorted by trial, the same on any number of workers. The
results go between `<!-- room_bench:start -->` and `<!-- room_bench:end -->` in docs/ROOM.md.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_sim.roomgen import STRATA  # noqa: E402
from tools.room.experiments import HELD, QUICK, Config, trials  # noqa: E402
from tools.room.report import write  # noqa: E402
from tools.room.trials import run_room_trial  # noqa: E402
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

LABEL = "room"


def run_bench(config: Config, executor: str = "local", workers: int = 2, only: set[int] | None = None,
              shard: Shard | None = None) -> list[dict[str, Any]]:
    """Every trial's result (wall seconds aside, the same whatever the executor and workers); with
    `only` or `shard`, those trials alone, numbered as in the whole campaign."""
    chosen = [(i, t) for i, t in enumerate(trials(config)) if (only is None or i in only)
              and (shard is None or shard.picks(i))]
    results = run_sweep(run_room_trial, [t for _, t in chosen], executor=executor, workers=workers,
                        label=LABEL)
    return [{**r, "trial": chosen[r["trial"]][0]} for r in results]


def _load() -> str:
    one, five, fifteen = os.getloadavg()
    return f"load average {one:.2f}, {five:.2f}, {fifteen:.2f}"


def _commit() -> str:
    """The commit the campaign ran at (with `+` when the work tree had changes), for the record."""
    def git(*args: str) -> str:
        return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True).stdout.strip()

    changed = git("status", "--porcelain", "--untracked-files=no")
    return git("rev-parse", "--short", "HEAD") + ("+" if changed else "")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true", help="a smoke run: two rooms, 20 simulated seconds")
    p.add_argument("--rooms", type=int, help="rooms per stratum (default 25)")
    p.add_argument("--strata", help=f"strata, comma-separated (default all: {','.join(STRATA)})")
    p.add_argument("--max-time", type=float, help="simulated seconds per room at most (default 2100)")
    p.add_argument("--trials", help="only these trial indices of the campaign, comma-separated")
    p.add_argument("--first-seed", type=int, help=f"the first seed of each stratum (default {HELD})")
    p.add_argument("--shard", help="I/N: run only trials I-1, I-1+N, ... and write them to --shards")
    p.add_argument("--shards", type=Path, default=Path("out/room-shards"), help="the shards' folder")
    p.add_argument("--merge", action="store_true",
                   help="no run: the docs from every shard in --shards (--workers: how many ran at once)")
    p.add_argument("--partial", action="store_true", help="with --merge: the shards there are, not all")
    p.add_argument("--commit", help="with --merge: the commit the shards ran at (when not run in a git tree)")
    add_executor_args(p)
    add_results_args(p, "room", "ROOM.md")
    args = p.parse_args(argv)
    config = QUICK if args.quick else Config()
    strata = tuple(x for x in args.strata.split(",") if x) if args.strata else None
    unknown = [x for x in strata or () if x not in STRATA]
    if unknown:
        print(f"room_bench: unknown strata {unknown}; strata: {', '.join(STRATA)}", file=sys.stderr)
        return 2
    numbers = {"rooms": args.rooms, "strata": strata, "max_time": args.max_time,
               "first_seed": args.first_seed}
    config = replace(config, **{name: v for name, v in numbers.items() if v is not None})
    only = {int(i) for i in args.trials.split(",") if i} if args.trials else None
    command = " ".join(["tools/room_bench.py", *(argv if argv is not None else sys.argv[1:])])
    if args.merge:
        try:
            paths = sorted(args.shards.glob(f"{LABEL}-*-of-*.jsonl"))
            results = merge_shards(paths, complete=not args.partial)
        except SweepError as exc:
            print(f"room_bench: {exc}", file=sys.stderr)
            return 2
        meta = json.loads((args.shards / "meta.json").read_text(encoding="utf-8"))
        saved = {"command": command, "wall": meta["end"] - meta["start"], "workers": args.workers,
                 "load": meta["load"], "commit": args.commit or meta["commit"], "results": results}
        save_results(args.raw, saved)
    elif args.saved:
        saved = json.loads(args.saved.read_text(encoding="utf-8"))
    else:
        load, commit = _load(), _commit()
        started = time.perf_counter()
        try:
            shard = Shard.parse(args.shard) if args.shard else None
            results = run_bench(config, args.executor, args.workers, only, shard)
        except SweepError as exc:
            print(f"room_bench: {exc}", file=sys.stderr)
            return 2
        saved = {"command": command, "wall": time.perf_counter() - started, "workers": args.workers,
                 "load": load, "commit": commit, "results": results}
        if shard:  # the merge's wall time: from the first shard's start to the last one's end
            write_shard(shard_path(args.shards, LABEL, shard), results, len(trials(config)))
            meta_path = args.shards / "meta.json"
            old = json.loads(meta_path.read_text(encoding="utf-8")) if meta_path.is_file() else {}
            now = time.time()
            meta = {"start": min(old.get("start", now), now - saved["wall"]),
                    "end": max(old.get("end", now), now), "load": old.get("load", load), "commit": commit}
            meta_path.write_text(json.dumps(meta) + "\n", encoding="utf-8")
            print(f"wrote shard {args.shard} ({len(results)} rooms)", file=sys.stderr)
            return 0
        save_results(args.raw, saved)
    lines = write(saved["results"], args.doc, args.figures, saved["command"], saved["wall"], saved["workers"],
                  f"{saved['load']}; at commit {saved.get('commit', '?')}")
    print("\n".join(lines))
    print(f"wrote {args.doc} and {args.figures} ({saved['wall'] / 60:.1f} min)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
