"""Held-out starts: random robot poses (and, with --move-table, a moved and turned table).

    .venv/bin/python tools/robustness.py --starts 30             # robots anywhere, table in the middle
    .venv/bin/python tools/robustness.py --starts 30 --move-table

Writes each drawn scenario to out/robustness/, runs them as paper_bench runs its trials, and prints
the success rate and every failure. Robots start at least `--clearance` m from the table, the walls
and each other.
"""

from __future__ import annotations

import argparse
import math
import random
import statistics
import sys
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.trial import TrialSpec  # noqa: E402
from tools.docsection import write_section  # noqa: E402
from tools.paper.results import succeeded  # noqa: E402
from tools.paper_bench import add_sweep_args, campaign, radio  # noqa: E402
from tools.sweep import SweepError  # noqa: E402

ROOM, LENGTH, WIDTH = 5.0, 0.8, 0.5


def _clear_of_table(x: float, y: float, table: dict[str, float], clearance: float) -> bool:
    yaw = math.radians(table["yaw"])
    dx, dy = x - table["x"], y - table["y"]
    along = abs(dx * math.cos(yaw) + dy * math.sin(yaw)) - LENGTH / 2
    across = abs(-dx * math.sin(yaw) + dy * math.cos(yaw)) - WIDTH / 2
    return max(along, across) >= clearance


def draw(rng: random.Random, move_table: bool, clearance: float) -> dict[str, Any]:
    table = {"x": 0.0, "y": 0.0, "yaw": 0.0, "length": LENGTH, "width": WIDTH}
    if move_table:
        table.update(x=round(rng.uniform(-0.6, 0.6), 2), y=round(rng.uniform(-0.6, 0.6), 2),
                     yaw=round(rng.uniform(0, 180), 1))
    robots: dict[str, dict[str, float]] = {}
    while len(robots) < 2:
        x, y = (round(rng.uniform(-ROOM / 2 + 0.6, ROOM / 2 - 0.6), 2) for _ in range(2))
        apart = all(math.dist((x, y), (r["x"], r["y"])) >= clearance for r in robots.values())
        if apart and _clear_of_table(x, y, table, clearance):
            robots[f"r{len(robots) + 1}"] = {"x": x, "y": y, "yaw": round(rng.uniform(-180, 180), 1)}
    return {"description": "a random held-out start", "task": "table_to_wall",
            "room": {"width": ROOM, "depth": ROOM}, "table": table, "robots": robots,
            "jitter": {"position": 0.0, "yaw": 0.0}}


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--starts", type=int, default=30)
    p.add_argument("--seed", type=int, default=1000, help="seeds the draws and the runs")
    p.add_argument("--move-table", action="store_true")
    p.add_argument("--clearance", type=float, default=0.8)
    add_sweep_args(p)
    p.add_argument("--out", type=Path, default=ROOT / "out" / "robustness")
    p.add_argument("--report", type=Path, help="also write the outcome as a section of this Markdown file")
    args = p.parse_args(argv)
    rng = random.Random(args.seed)
    args.out.mkdir(parents=True, exist_ok=True)
    specs = []
    for i in range(args.starts):
        path = args.out / f"start{i:03d}{'-table' if args.move_table else ''}.yaml"
        path.write_text(yaml.safe_dump(draw(rng, args.move_table, args.clearance), sort_keys=False))
        specs.append(TrialSpec(str(ROOT / "machines" / "move_furniture.yaml"), str(path), args.seed + i,
                               **radio(args)))
    label = "held-out-table" if args.move_table else "held-out"
    try:
        trials = campaign(specs, args, label)
    except SweepError as exc:
        print(f"robustness: {exc}", file=sys.stderr)
        return 2
    if trials is None:
        return 0
    ok = [t for t in trials if succeeded(t)]
    times = [t["time"] for t in ok]
    mean = f", mean {statistics.fmean(times) / 60:.1f} min, max {max(times) / 60:.1f} min" if times else ""
    lines = [f"{len(ok)}/{len(trials)} succeeded{mean}"]
    for t in trials:
        if not succeeded(t):
            table = yaml.safe_load(Path(t["spec"]["scenario"]).read_text())["table"]
            pose = f"table at ({table['x']}, {table['y']}), yaw {table['yaw']} deg"
            lines.append(f"- {Path(t['spec']['scenario']).name}, {pose}: {t['error'] or t['score']}")
    print("\n".join(lines))
    if args.report:
        name = "robustness_table" if args.move_table else "robustness"
        command = f"`.venv/bin/python tools/robustness.py --starts {args.starts} --seed {args.seed}"
        command += " --move-table`" if args.move_table else "`"
        write_section(args.report, name, [f"Command: {command}", "", *lines])
    return 0 if len(ok) == len(trials) else 1


if __name__ == "__main__":
    sys.exit(main())
