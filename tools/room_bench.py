"""Clear the room (issue 10): a seeded campaign of machines/clear_room.yaml in generated rooms.

    nice -n 10 .venv/bin/python tools/room_bench.py              # the campaign, docs/ROOM.md
    .venv/bin/python tools/room_bench.py --quick                 # a smoke run (2 rooms, 20 sim s)
    .venv/bin/python tools/room_bench.py --from docs/results/room.json   # the docs again, no run

The issue's target rooms (3 tables, 6-8 robots, one robot failing at a random time), then time
against K (2-5 tables, N = 2K) and N (6-9 robots, K = 3), then 30 % radio loss. Each trial draws its
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
from tools.sweep import SweepError, add_executor_args, run_sweep  # noqa: E402


def run_bench(config: Config, executor: str = "local", workers: int = 2) -> list[dict[str, Any]]:
    """Every trial's result (wall seconds aside, the same whatever the executor and workers)."""
    return run_sweep(run_room_trial, trials(config), executor=executor, workers=workers, label="room")


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
    p.add_argument("--rooms", type=int, help="target rooms (3 tables, 6-8 robots, one failure)")
    p.add_argument("--ks", help="table counts of the time-against-K rooms, comma-separated (default 2,3,4,5)")
    p.add_argument("--ns", help="robot counts of the time-against-N rooms, comma-separated (default 6,7,8,9)")
    p.add_argument("--loss-rooms", type=int, help="rooms at 30 %% radio loss (default 2)")
    p.add_argument("--max-time", type=float, help="simulated seconds per room at most (default 2100)")
    p.add_argument("--first-seed", type=int, default=1)
    add_executor_args(p)
    p.add_argument("--doc", type=Path, default=ROOT / "docs" / "ROOM.md")
    p.add_argument("--figures", type=Path, default=ROOT / "docs" / "figures" / "room")
    p.add_argument("--raw", type=Path, default=ROOT / "docs" / "results" / "room.json")
    p.add_argument("--from", dest="saved", type=Path, help="no run: write the docs again from a --raw file")
    args = p.parse_args(argv)
    config = replace(QUICK if args.quick else Config(), first_seed=args.first_seed)
    if args.rooms is not None:
        config = replace(config, target_rooms=args.rooms)
    if args.ks is not None:
        config = replace(config, ks=tuple(int(k) for k in args.ks.split(",") if k))
    if args.ns is not None:
        config = replace(config, ns=tuple(int(n) for n in args.ns.split(",") if n))
    if args.loss_rooms is not None:
        config = replace(config, loss_rooms=args.loss_rooms)
    if args.max_time is not None:
        config = replace(config, max_time=args.max_time)
    if args.saved:
        saved = json.loads(args.saved.read_text(encoding="utf-8"))
    else:
        load, commit = _load(), _commit()
        started = time.perf_counter()
        try:
            results = run_bench(config, args.executor, args.workers)
        except SweepError as exc:
            print(f"room_bench: {exc}", file=sys.stderr)
            return 2
        command = " ".join(["tools/room_bench.py", *(argv if argv is not None else sys.argv[1:])])
        saved = {"command": command, "wall": time.perf_counter() - started, "workers": args.workers,
                 "load": load, "commit": commit, "results": results}
        args.raw.parent.mkdir(parents=True, exist_ok=True)
        args.raw.write_text(json.dumps(saved, indent=1) + "\n", encoding="utf-8")
    lines = write(saved["results"], args.doc, args.figures, saved["command"], saved["wall"], saved["workers"],
                  f"{saved['load']}; at commit {saved.get('commit', '?')}")
    print("\n".join(lines))
    print(f"wrote {args.doc} and {args.figures} ({saved['wall'] / 60:.1f} min)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
