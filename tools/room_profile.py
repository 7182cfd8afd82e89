"""Where a room run's time goes, from cProfile files of whole `hfsm-run` commands.

Usage:
    nice -n 5 .venv/bin/python -m cProfile -o ROOM.prof .venv/bin/hfsm-run machines/clear_room.yaml \\
        --scenario ROOM.yaml --seed 0 --json --no-video --trace ROOM.jsonl
    .venv/bin/python tools/room_profile.py ROOM.prof [MORE.prof ...]

Prints a Markdown table: for each part of the run (physics, the bodies' Python after every step,
cameras, laser, the engine's ticks, the trace), its cumulative seconds as a share of the profiled
total. Rows nest (the engine's ticks include the sensors they read, which include the cameras), so
the shares compare and do not add up; cProfile inflates Python's many small calls.
"""

from __future__ import annotations

import argparse
import pstats
from pathlib import Path

# (row, [(file suffix, function)], "cum" or "tot"): a row sums the functions' times
ROWS: list[tuple[str, list[tuple[str, str]], str]] = [
    ("world advance (physics steps and the Python run after each)",
     [("hfsm_behaviours/simworld.py", "advance")], "cum"),
    ("  physics (`stepSimulation`, 120 Hz)", [("~", "<built-in method pybullet.stepSimulation>")], "tot"),
    ("  mocap leash of the walking bodies (`_pre_step`)", [("hfsm_sim/base.py", "_pre_step")], "cum"),
    ("  lifting rules (`Lifting.update`)", [("hfsm_sim/lifting.py", "update")], "cum"),
    ("  contact scoring (`Scorer.observe`)", [("hfsm_sim/scorer.py", "observe")], "cum"),
    ("engine ticks (machines and behaviours, sensors read in them)", [("hfsm/runtime/run.py", "_step_all")],
     "cum"),
    ("  sensors (`SimWorld.read_input`)", [("hfsm_behaviours/simworld.py", "read_input")], "cum"),
    ("    camera images drawn (`Rasteriser.render`)", [("hfsm_sim/raster.py", "render")], "cum"),
    ("    images read (`find_table`, `see_tables`, `find_robots`)",
     [("hfsm_sim/perception/blobs.py", "find_table"), ("hfsm_sim/perception/tables.py", "see_tables"),
      ("hfsm_sim/perception/blobs.py", "find_robots")], "cum"),
    ("  laser scans (`Base.scan`, `rayTestBatch`)", [("hfsm_sim/base.py", "scan")], "cum"),
    ("pose records for the monitor (`trace_records`)", [("hfsm_behaviours/simworld.py", "trace_records")],
     "cum"),
    ("trace written (`flush` of the records)", [("hfsm/runtime/records.py", "flush")], "cum"),
    ("messages delivered (`Engine.deliver`)", [("hfsm/runtime/engine.py", "deliver")], "cum"),
]


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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("profiles", nargs="+", type=Path)
    args = parser.parse_args()
    columns = []
    for path in args.profiles:
        stats = pstats.Stats(str(path))
        columns.append((path.stem, stats.total_tt, _times(stats)))  # type: ignore[attr-defined]
    print("| where | " + " | ".join(f"{name} ({total:.0f} s)" for name, total, _ in columns) + " |")
    print("|---|" + "---:|" * len(columns))
    for label, parts, kind in ROWS:
        cells = []
        for _, total, times in columns:
            seconds = row_seconds(times, parts, kind)
            cells.append(f"{100 * seconds / total:.0f} %")
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
