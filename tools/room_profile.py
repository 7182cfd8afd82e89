"""Where a room run's time goes, from cProfile files of whole `hfsm-run` commands.

Usage:
    .venv/bin/python tools/room_profile.py --run ROOM.yaml --max-time 100 -o ROOM.prof   # profile a run
    .venv/bin/python tools/room_profile.py ROOM.prof [MORE.prof ...]                     # the table

`--run` profiles `hfsm-run machines/clear_room.yaml --scenario ROOM.yaml --seed 0 --json --no-video
--trace FILE` in process on CPU time (`time.process_time`: other work on a shared machine does not
count); `python -m cProfile -o F .venv/bin/hfsm-run ...` gives a profile on the wall clock.

Prints a Markdown table: for each part of the run (physics, the bodies' Python after every step,
cameras, laser, the engine's ticks, the trace), its cumulative seconds as a share of the profiled
total. Rows nest (the engine's ticks include the sensors they read, which include the cameras), so
the shares compare and do not add up; cProfile inflates Python's many small calls.
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

# (row, [(file suffix, function)], "cum" or "tot", disjoint): a row sums the functions' times; the
# disjoint rows do not hold one another, and the last row is the total less them
ROWS: list[tuple[str, list[tuple[str, str]], str, bool]] = [
    ("world advance: physics steps and the Python after each", [("hfsm_sim/world.py", "advance")], "cum",
     True),
    ("  physics (`stepSimulation`, 120 Hz)", [("~", "<built-in method pybullet.stepSimulation>")], "tot",
     False),
    ("  leash of the walking bodies (`_pre_step`)", [("hfsm_sim/base.py", "_pre_step")], "cum", False),
    ("  lifting rules (`Lifting.update`)", [("hfsm_sim/lifting.py", "update")], "cum", False),
    ("  contact scoring (`Scorer.observe`)", [("hfsm_sim/scorer.py", "observe")], "cum", False),
    ("camera images drawn (`Rasteriser.render`)", [("hfsm_sim/raster.py", "render")], "cum", True),
    ("images read (`find_table`, `see_tables`, `find_robots`)",
     [("hfsm_sim/perception/blobs.py", "find_table"), ("hfsm_sim/perception/tables.py", "see_tables"),
      ("hfsm_sim/perception/blobs.py", "find_robots")], "cum", True),
    ("laser scans (`Base.scan`)", [("hfsm_sim/base.py", "scan")], "cum", True),
    ("  of which `rayTestBatch`", [("~", "<built-in method pybullet.rayTestBatch>")], "tot", False),
    ("looking for messages in the mailboxes (`Mailbox.take`)", [("hfsm/runtime/mailbox.py", "take")], "cum",
     True),
    ("pose records for the monitor (`trace_records`)", [("hfsm_behaviours/simworld.py", "trace_records")],
     "cum", True),
    ("trace written (records' `flush`, `TraceFile.write`)",
     [("hfsm/runtime/records.py", "flush"), ("hfsm/cli/tracefile.py", "write")], "cum", True),
]
REST = "the rest: engine, machines and behaviours' own Python, start-up"


def _times(stats: pstats.Stats) -> dict[tuple[str, str], tuple[float, float]]:
    out: dict[tuple[str, str], tuple[float, float]] = {}
    raw = stats.stats  # type: ignore[attr-defined]
    for (file, _, name), (_, _, tot, cum, _) in raw.items():
        key = (file, name)
        old = out.get(key, (0.0, 0.0))
        out[key] = (old[0] + tot, old[1] + cum)
    return out


def row_seconds(times: dict[tuple[str, str], tuple[float, float]], parts: list[tuple[str, str]],
                kind: str) -> float:
    total = 0.0
    for suffix, name in parts:
        for (file, func), (tot, cum) in times.items():
            if func == name and file.endswith(suffix):
                total += tot if kind == "tot" else cum
    return total


def profile_run(scenario: Path, max_time: float, out: Path) -> None:
    from hfsm.cli.run import main as hfsm_run

    with tempfile.TemporaryDirectory() as tmp:
        argv = [str(ROOT / "machines" / "clear_room.yaml"), "--scenario", str(scenario), "--seed", "0",
                "--json", "--no-video", "--quiet", "--progress", "0", "--max-time", str(max_time),
                "--trace", str(Path(tmp) / "trace.jsonl")]
        profiler = cProfile.Profile(time.process_time)
        stdout, sys.stdout = sys.stdout, sys.stderr  # the run's JSON is not the table
        try:
            profiler.runcall(hfsm_run, argv)
        finally:
            sys.stdout = stdout
        profiler.dump_stats(str(out))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("profiles", nargs="*", type=Path)
    parser.add_argument("--run", type=Path, help="a room's scenario file to profile")
    parser.add_argument("--max-time", type=float, default=100.0)
    parser.add_argument("-o", type=Path, help="where --run writes its profile")
    args = parser.parse_args()
    if args.run is not None:
        profile_run(args.run, args.max_time, args.o or Path(args.run.stem + ".prof"))
        return
    columns = []
    for path in args.profiles:
        stats = pstats.Stats(str(path))
        columns.append((path.stem, stats.total_tt, _times(stats)))  # type: ignore[attr-defined]
    print("| where | " + " | ".join(f"{name} ({total:.0f} s)" for name, total, _ in columns) + " |")
    print("|---|" + "---:|" * len(columns))
    rest = [total for _, total, _ in columns]
    for label, parts, kind, disjoint in ROWS:
        cells = []
        for i, (_, total, times) in enumerate(columns):
            seconds = row_seconds(times, parts, kind)
            if disjoint:
                rest[i] -= seconds
            cells.append(f"{100 * seconds / total:.0f} %")
        print(f"| {label} | " + " | ".join(cells) + " |")
    print(f"| {REST} | " + " | ".join(f"{100 * r / c[1]:.0f} %" for r, c in zip(rest, columns, strict=True))
          + " |")


if __name__ == "__main__":
    main()
