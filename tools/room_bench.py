"""Clear the room (issue 10): a seeded campaign of machines/clear_room.yaml in generated rooms.

    nice -n 10 .venv/bin/python tools/room_bench.py              # the campaign, docs/ROOM.md
    .venv/bin/python tools/room_bench.py --quick                 # a smoke run (2 rooms, 20 sim s)
    .venv/bin/python tools/room_bench.py --from docs/results/room.json   # the docs again, no run

The issue's target rooms (3 tables, 6-8 robots, one robot failing at a random time), then time
against K (2-5 tables) and N (2K-2K+3 robots) with and without a failure, then failure rates (the
scenario's `rate:` form), then the first target rooms again at 10 % and 30 % radio loss.
`--trials 0,40,72` runs only those trials of the campaign (a slice, to time it). Each trial draws its
room from its seed (tools/room/scenes.py) into a temporary folder and runs it headless through the
run API hfsm-run uses; trials run in parallel processes (or on a Dask cluster) through
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

from tools.room.experiments import QUICK, Config, trials  # noqa: E402
from tools.room.report import write  # noqa: E402
from tools.room.trials import run_room_trial  # noqa: E402
from tools.sweep import SweepError, add_executor_args, add_results_args, run_sweep, save_results  # noqa: E402


def run_bench(config: Config, executor: str = "local", workers: int = 2, only: set[int] | None = None
              ) -> list[dict[str, Any]]:
    """Every trial's result (wall seconds aside, the same whatever the executor and workers); with
    `only`, those trials alone, numbered as in the whole campaign."""
    chosen = [(i, t) for i, t in enumerate(trials(config)) if only is None or i in only]
    results = run_sweep(run_room_trial, [t for _, t in chosen], executor=executor, workers=workers,
                        label="room")
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
    p.add_argument("--rooms", type=int, help="target rooms (3 tables, 6-8 robots, one failure; default 40)")
    p.add_argument("--ks", help="table counts of the K-N rooms, comma-separated (default 2,3,4,5)")
    p.add_argument("--extra", help="robots beyond 2K in the K-N rooms, comma-separated (default 0,1,2,3)")
    p.add_argument("--kn-seeds", type=int, help="seeds per K and N: the first without failure (default 2)")
    p.add_argument("--rates", help="failures per robot per minute of the rate rooms (default 0.02,0.05)")
    p.add_argument("--rate-seeds", type=int, help="rooms per rate (default 3)")
    p.add_argument("--losses", help="radio losses the first target rooms run again at (default 0.1,0.3)")
    p.add_argument("--loss-rooms", type=int, help="target rooms run again at each loss (default 4)")
    p.add_argument("--max-time", type=float, help="simulated seconds per target room at most (default 2100)")
    p.add_argument("--other-max-time", type=float,
                   help="simulated seconds per room of the other sets at most (default 600)")
    p.add_argument("--trials", help="only these trial indices of the campaign, comma-separated")
    p.add_argument("--first-seed", type=int, default=1)
    add_executor_args(p)
    add_results_args(p, "room", "ROOM.md")
    args = p.parse_args(argv)
    config = replace(QUICK if args.quick else Config(), first_seed=args.first_seed)
    numbers: dict[str, Any] = {"target_rooms": args.rooms, "kn_seeds": args.kn_seeds,
                               "rate_seeds": args.rate_seeds, "loss_rooms": args.loss_rooms,
                               "max_time": args.max_time, "other_max_time": args.other_max_time}
    lists = {"ks": (args.ks, int), "extra": (args.extra, int), "rates": (args.rates, float),
             "losses": (args.losses, float)}
    numbers.update({name: tuple(kind(x) for x in text.split(",") if x) for name, (text, kind) in lists.items()
                    if text is not None})
    config = replace(config, **{name: v for name, v in numbers.items() if v is not None})
    only = {int(i) for i in args.trials.split(",") if i} if args.trials else None
    if args.saved:
        saved = json.loads(args.saved.read_text(encoding="utf-8"))
    else:
        load, commit = _load(), _commit()
        started = time.perf_counter()
        try:
            results = run_bench(config, args.executor, args.workers, only)
        except SweepError as exc:
            print(f"room_bench: {exc}", file=sys.stderr)
            return 2
        command = " ".join(["tools/room_bench.py", *(argv if argv is not None else sys.argv[1:])])
        saved = {"command": command, "wall": time.perf_counter() - started, "workers": args.workers,
                 "load": load, "commit": commit, "results": results}
        save_results(args.raw, saved)
    lines = write(saved["results"], args.doc, args.figures, saved["command"], saved["wall"], saved["workers"],
                  f"{saved['load']}; at commit {saved.get('commit', '?')}")
    print("\n".join(lines))
    print(f"wrote {args.doc} and {args.figures} ({saved['wall'] / 60:.1f} min)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
