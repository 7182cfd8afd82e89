"""Success of the paper's six configurations against the radio's loss and latency.

    .venv/bin/python tools/radio_sweep.py --losses 0,0.1,0.2,0.3,0.5 --trials 10
    .venv/bin/python tools/radio_sweep.py --losses 0 --latency 2 --trials 10

Runs machines/move_furniture.yaml on every configuration and seed at each loss rate (trials in
parallel processes, as paper_bench runs them) and prints one Markdown row per rate: successes,
mean and max task time, dropped tables and runs with a robot-robot collision, and every failure.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.trial import TrialSpec, run_trial_dict  # noqa: E402
from tools.docsection import write_section  # noqa: E402
from tools.paper.reference import SCENARIOS  # noqa: E402
from tools.paper.results import succeeded  # noqa: E402
from tools.sweep import SweepError, run_sweep  # noqa: E402

HEAD = ["loss", "latency s", "succeeded", "mean min", "max min", "dropped", "runs with collisions"]


def row(loss: float, latency: float, trials: list[dict[str, Any]]) -> str:
    times = [t["time"] / 60 for t in trials]
    ok = sum(succeeded(t) for t in trials)
    dropped = sum(bool(t["score"]["dropped"]) for t in trials)
    collided = sum(t["score"]["robot_collisions"] > 0 for t in trials)
    cells = [f"{loss:g}", f"{latency:g}", f"{ok}/{len(trials)}", f"{statistics.fmean(times):.1f}",
             f"{max(times):.1f}", str(dropped), str(collided)]
    return "| " + " | ".join(cells) + " |"


def failures(trials: list[dict[str, Any]]) -> list[str]:
    return [f"- loss {t['spec']['radio_loss']:g}, {t['spec']['scenario']} seed {t['spec']['seed']}: "
            f"{t['error'] or t['score']}, outcomes {t['outcomes']}" for t in trials if not succeeded(t)]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--losses", default="0,0.1,0.2,0.3,0.5", help="comma-separated loss rates")
    p.add_argument("--latency", type=float, default=0.1, help="seconds every message takes")
    p.add_argument("--trials", type=int, default=10, help="seeds per configuration")
    p.add_argument("--seed", type=int, default=0, help="first seed")
    p.add_argument("--workers", type=int, default=2, help="local processes")
    p.add_argument("--max-time", type=float, default=2400.0, help="simulated seconds per trial")
    p.add_argument("--report", type=Path, help="also write the table as a section of this Markdown file")
    p.add_argument("--section", default="radio_loss", help="the section's name in --report")
    args = p.parse_args(argv)
    machine = str(ROOT / "machines" / "move_furniture.yaml")
    lines, failed = ["| " + " | ".join(HEAD) + " |", "|" + "---|" * len(HEAD)], []
    started = time.perf_counter()
    for loss in (float(x) for x in args.losses.split(",")):
        specs = [TrialSpec(machine, scenario, seed, {}, args.max_time, radio_latency=args.latency,
                           radio_loss=loss)
                 for scenario, _ in SCENARIOS for seed in range(args.seed, args.seed + args.trials)]
        try:
            trials = run_sweep(run_trial_dict, specs, workers=args.workers, label=f"loss {loss:g}")
        except SweepError as exc:
            print(f"radio_sweep: {exc}", file=sys.stderr)
            return 2
        lines.append(row(loss, args.latency, trials))
        failed += failures(trials)
    flags = " ".join(argv if argv is not None else sys.argv[1:])
    command = f"`.venv/bin/python tools/radio_sweep.py {flags}`"
    minutes = (time.perf_counter() - started) / 60
    out = [f"Command: {command} ({minutes:.0f} min of wall time on 2 cores)", "", *lines, "",
           *(failed or ["No trial failed."])]
    print("\n".join(out))
    if args.report:
        write_section(args.report, args.section, out)
    return 0 if not failed else 1


if __name__ == "__main__":
    sys.exit(main())
