"""Issue 10's campaign: rooms of K tables and N humanoids cleared by machines/clear_room.yaml.

    nice -n 10 .venv/bin/python tools/room_bench.py           # the campaign, docs/ROOM.md
    .venv/bin/python tools/room_bench.py --quick              # a smoke run (2 rooms)
    .venv/bin/python tools/room_bench.py --from docs/results/room.json   # the docs again, no run

Rooms are generated (tools/room/scenes.py) from (K, N, seed, failure); every trial is seeded and
runs in its own process through tools/sweep.py (2 local workers, or a Dask cluster), results sorted
by trial. A room is cleared when the scorer finds every table within 0.15 m of a wall.
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

from tools.docsection import write_section  # noqa: E402
from tools.room.report import success_plot, summary_lines, table_lines, time_plot  # noqa: E402
from tools.room.trials import RoomTrial, run_room_trial  # noqa: E402
from tools.sweep import SweepError, run_sweep  # noqa: E402


def campaign(seeds: int, first: int = 0) -> list[RoomTrial]:
    """No failure in rooms of 2 and 3 tables with fewest and most robots, 4 tables once; one robot
    failing on its way or in the carry; 30 % radio loss."""
    out: list[RoomTrial] = []
    for s in range(first, first + seeds):
        out += [RoomTrial(2, 4, s), RoomTrial(2, 6, s), RoomTrial(3, 6, s), RoomTrial(3, 8, s)]
        out += [RoomTrial(3, 6, s, "early"), RoomTrial(3, 8, s, "early"), RoomTrial(3, 8, s, "mid")]
        out += [RoomTrial(2, 4, s, loss=0.3)]
    out.append(RoomTrial(4, 8, first))
    return out


QUICK = [RoomTrial(2, 4, 0), RoomTrial(2, 4, 0, "early")]


def write_docs(saved: dict[str, Any], doc: Path, figures: Path) -> list[str]:
    results = saved["results"]
    time_plot(results, figures / "time.png")
    success_plot(results, figures / "cleared.png")
    rel = figures.relative_to(doc.parent) if figures.is_relative_to(doc.parent) else figures
    lines = [f"Command: `{saved['command']}` ({len(results)} rooms, {saved['wall'] / 60:.1f} min wall with "
             f"{saved['workers']} worker processes on the shared 2-core machine). Times are simulated "
             "seconds.",
             "", *summary_lines(results), "", *table_lines(results), "",
             f"![time to clear]({rel}/time.png) ![rooms cleared]({rel}/cleared.png)"]
    write_section(doc, "room_bench", lines)
    return lines


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quick", action="store_true", help="a smoke run: two rooms")
    p.add_argument("--seeds", type=int, default=2, help="seeds per room kind")
    p.add_argument("--first-seed", type=int, default=0)
    p.add_argument("--workers", type=int, default=2, help="local processes (with --executor local)")
    p.add_argument("--executor", default="local", help="local, or dask://HOST:PORT for a Dask cluster")
    p.add_argument("--doc", type=Path, default=ROOT / "docs" / "ROOM.md")
    p.add_argument("--figures", type=Path, default=ROOT / "docs" / "figures" / "room")
    p.add_argument("--raw", type=Path, default=ROOT / "docs" / "results" / "room.json")
    p.add_argument("--from", dest="saved", type=Path, help="no run: write the docs again from a --raw file")
    args = p.parse_args(argv)
    if args.saved:
        saved = json.loads(args.saved.read_text(encoding="utf-8"))
    else:
        trials = QUICK if args.quick else campaign(args.seeds, args.first_seed)
        started = time.perf_counter()
        try:
            results = run_sweep(run_room_trial, trials, executor=args.executor, workers=args.workers,
                                label="rooms")
        except SweepError as exc:
            print(f"room_bench: {exc}", file=sys.stderr)
            return 2
        command = " ".join(["tools/room_bench.py", *(argv if argv is not None else sys.argv[1:])])
        saved = {"command": command, "wall": time.perf_counter() - started, "workers": args.workers,
                 "results": results}
        args.raw.parent.mkdir(parents=True, exist_ok=True)
        args.raw.write_text(json.dumps(saved, indent=1) + "\n", encoding="utf-8")
    lines = write_docs(saved, args.doc.resolve(), args.figures.resolve())
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
