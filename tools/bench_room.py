"""Wall and CPU seconds per simulated second of whole room runs, this tree against another revision.

Usage: .venv/bin/python tools/bench_room.py [--rev main] [--now REV] [--robots 4,8,12] [--seconds 60]
       [--rounds 3] [--no-doc]

Rooms of 4, 8 and 12 humanoids are drawn by the generator (hfsm_sim.roomgen: the first development
seed of the strata below with that many robots) and written to a temporary folder; each runs as
`hfsm-run machines/clear_room.yaml --scenario FILE --seed 0 --json --no-video --max-time SECONDS
--trace FILE` in a fresh process, once with this tree's code and once with `git archive REV` of the
code and machines unpacked into a temporary folder and put first on PYTHONPATH (as
tools/bench_before.py does), in turn (order alternated by round); `--now REV` runs a revision
unpacked the same way instead of this tree (so the tree can change while the bench runs). Per run:
wall seconds (`perf_counter` around the process) and CPU seconds (user + system of the child),
over the simulated seconds it ran; a figure is the median over rounds. The traces of the two trees
are compared byte for byte (sha256) in every round. Rewrites the bench_room section of docs/PERFORMANCE.md.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
for folder in (ROOT, ROOT / "tools"):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))

from docsection import write_section  # noqa: E402

from hfsm_sim import roomgen  # noqa: E402

DOC = ROOT / "docs" / "PERFORMANCE.md"
STRATA = ("open", "crowded", "close", "walls", "narrow")  # searched in this order for a room
CODE = ("hfsm", "hfsm_behaviours", "hfsm_sim", "machines")
MAX_SEED = 400


def pick_room(robots: int) -> tuple[str, int, dict[str, Any]]:
    """The first (stratum, seed) of STRATA x 1..MAX_SEED whose room has `robots` robots."""
    for seed in range(1, MAX_SEED):
        for stratum in STRATA:
            scenario = roomgen.draw(seed, stratum)
            if len(scenario["robots"]) == robots:
                return stratum, seed, scenario
    raise SystemExit(f"no room of {robots} robots among the strata's seeds 1-{MAX_SEED}")


def unpack(rev: str, into: Path) -> str:
    """`git archive REV` of the code and machines into `into`; the revision's short hash."""
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev, *CODE], capture_output=True,
                             check=True).stdout
    subprocess.run(["tar", "-x", "-C", str(into)], input=archive, check=True)
    return subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", rev], capture_output=True,
                          text=True, check=True).stdout.strip()


def run_once(tree: Path, scenario: Path, seconds: float, trace: Path) -> dict[str, Any]:
    """One whole hfsm-run of the room with the code of `tree`: wall and CPU seconds, simulated seconds,
    the trace's sha256 and the score."""
    env = dict(os.environ, PYTHONPATH=str(tree), PYTHONHASHSEED="0")
    cmd = [sys.executable, "-m", "hfsm.cli.run", str(tree / "machines" / "clear_room.yaml"),
           "--scenario", str(scenario), "--seed", "0", "--json", "--no-video", "--quiet",
           "--progress", "0", "--max-time", str(seconds), "--trace", str(trace)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    begin = time.perf_counter()
    done = subprocess.run(cmd, cwd=tree, env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - begin
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:  # a run stopped at --max-time exits 1 and still prints its score
        simulated = float(json.loads(done.stdout)["score"]["time"])
    except (ValueError, KeyError):
        raise SystemExit(f"{' '.join(cmd)} exited {done.returncode}:\n{done.stderr[-2000:]}") from None
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    digest = hashlib.sha256(trace.read_bytes()).hexdigest()
    trace.unlink()
    return {"wall": wall, "cpu": cpu, "simulated": simulated, "sha": digest}


def bench(rev: str, robots: list[int], seconds: float, rounds: int, now: str | None) -> dict[str, Any]:
    rooms = {n: pick_room(n) for n in robots}
    rows: dict[int, dict[str, list[dict[str, Any]]]] = {n: {"before": [], "now": []} for n in robots}
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)
        old = base / "before"
        old.mkdir()
        short = unpack(rev, old)
        trees = {"before": old, "now": ROOT}
        if now is not None:
            trees["now"] = base / "now"
            trees["now"].mkdir()
            now = unpack(now, trees["now"])
        for n, (stratum, seed, scenario) in rooms.items():
            path = base / f"{stratum}-{seed}.yaml"
            roomgen.write(path, scenario)
            for r in range(rounds):
                order = ("before", "now") if r % 2 == 0 else ("now", "before")
                for which in order:
                    run = run_once(trees[which], path, seconds, base / f"{which}.jsonl")
                    rows[n][which].append(run)
                    print(f"{n} robots ({stratum}-{seed}) round {r + 1} {which}: wall {run['wall']:.1f} s, "
                          f"CPU {run['cpu']:.1f} s for {run['simulated']:.1f} simulated s", flush=True)
    return {"rev": rev, "short": short, "rooms": {n: rooms[n][:2] for n in robots}, "rows": rows,
            "seconds": seconds, "rounds": rounds, "now": now}


def _median(runs: list[dict[str, Any]], key: str) -> float:
    return statistics.median(run[key] / run["simulated"] for run in runs)


def report(data: dict[str, Any], took: float) -> list[str]:
    rev, short = data["rev"], data["short"]
    load = os.getloadavg()[0]
    lines = [
        f"Measured by `tools/bench_room.py` on {platform.machine()}, {os.cpu_count()} CPUs, Python "
        f"{platform.python_version()}, {time.strftime('%Y-%m-%d')}; before: `{rev}` ({short}), now: "
        f"{data['now'] or 'this tree'}; load "
        f"average at the end {load:.1f} (shared 2-core VM: CPU seconds are the steadier figure); "
        f"{took / 60:.0f} min in all.",
        f"Command: `.venv/bin/python tools/bench_room.py --rev {rev}"
        f"{' --now ' + data['now'] if data['now'] else ''} --robots "
        f"{','.join(str(n) for n in data['rows'])} --seconds {data['seconds']:g} --rounds {data['rounds']}`"
        f" (each run `hfsm-run machines/clear_room.yaml --scenario FILE --seed 0 --json --no-video "
        f"--max-time {data['seconds']:g} --trace FILE`, start-up included; medians of the rounds, the "
        "trees in turn).",
        "",
        "| robots | room (stratum-seed) | before: wall s / sim s | before: CPU s / sim s "
        "| now: wall s / sim s | now: CPU s / sim s | now / before (CPU) | same trace |",
        "|---:|---|---:|---:|---:|---:|---:|---|",
    ]
    for n, runs in data["rows"].items():
        stratum, seed = data["rooms"][n]
        before, now = runs["before"], runs["now"]
        same = all(a["sha"] == b["sha"] for a, b in zip(before, now, strict=True))
        cpu_b, cpu_n = _median(before, "cpu"), _median(now, "cpu")
        lines.append(f"| {n} | `{stratum}-{seed}` | {_median(before, 'wall'):.3f} | {cpu_b:.3f} | "
                     f"{_median(now, 'wall'):.3f} | {cpu_n:.3f} | {cpu_n / cpu_b:.2f}x | "
                     f"{'yes' if same else 'no'} |")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rev", default="main", help="the revision to compare with (default main)")
    parser.add_argument("--now", help="a revision to run as now (default: this tree as it is)")
    parser.add_argument("--robots", default="4,8,12", help="room sizes, comma-separated")
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated seconds a run")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--no-doc", action="store_true", help="print, do not rewrite docs/PERFORMANCE.md")
    args = parser.parse_args()
    begin = time.perf_counter()
    data = bench(args.rev, [int(n) for n in args.robots.split(",")], args.seconds, args.rounds, args.now)
    lines = report(data, time.perf_counter() - begin)
    print("\n".join(lines))
    if not args.no_doc:
        write_section(DOC, "bench_room", lines)


if __name__ == "__main__":
    main()
