"""Copying a state in hfsm-verify: the CPU time of a dump (a state to bytes) and a load (a copy back)
by this code's `hfsm/verify/snapshot.py` and by another version of that file, on the same states of
one search, the two interleaved in rounds so that the machine's load falls on both alike.

Prints microseconds a dump and a load (fastest round, and the median round) for each.
Usage: nice -n 15 .venv/bin/python tools/bench_copy.py OTHER_SNAPSHOT_PY [--rounds N] [hfsm-verify args]
(e.g. `git show main:hfsm/verify/snapshot.py > /tmp/main_snapshot.py` for OTHER_SNAPSHOT_PY;
default search: machines/move_furniture.yaml --agents r1,r2 --loss 1 --fail 1 --max-states 3000)
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import io
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from hfsm.cli import verify as verify_cli
from hfsm.verify import search, snapshot

ROOT = Path(__file__).resolve().parent.parent
DEFAULT = [str(ROOT / "machines" / "move_furniture.yaml"), "--agents", "r1,r2", "--loss", "1", "--fail", "1",
           "--max-states", "3000"]  # fmt: skip
KEEP = 400  # states kept, spread over the search


def _other(path: Path) -> Any:
    spec = importlib.util.spec_from_file_location("other_snapshot", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["other_snapshot"] = module  # its pickles name functions of it
    spec.loader.exec_module(module)
    return module


def _states(args: list[str]) -> tuple[list[Any], dict[int, Any]]:
    """Engines the search reaches (copies of them, by this code), and what its states share."""
    reached: list[bytes] = []
    made: list[Any] = []
    visit = search.Search.visit

    def recording(self: search.Search, engine: Any, ended: Any, parent: int) -> bool:
        if ended is None and engine.running:
            reached.append(self.snaps.dump(engine))
            made.append(self)
        return visit(self, engine, ended, parent)

    search.Search.visit = recording  # type: ignore[method-assign]
    close = snapshot.Snapshots.close
    snapshot.Snapshots.close = lambda self: None  # type: ignore[method-assign]
    try:
        with (
            tempfile.TemporaryDirectory() as folder,
            contextlib.redirect_stdout(io.StringIO()),
            contextlib.redirect_stderr(io.StringIO()),
        ):
            verify_cli.main([*args, "--json", "--out", str(Path(folder) / "ce.jsonl")])
    finally:
        search.Search.visit = visit  # type: ignore[method-assign]
        snapshot.Snapshots.close = close  # type: ignore[method-assign]
    found = made[0]
    step = max(1, len(reached) // KEEP)
    return [found.snaps.load(d) for d in reached[::step]], found.snaps.shared


def _round(snaps: Any, engines: list[Any]) -> tuple[float, float]:
    clock = time.thread_time
    start = clock()
    datas = [snaps.dump(e) for e in engines]
    dumped = clock() - start
    start = clock()
    for data in datas:
        snaps.load(data)
    return dumped / len(engines), (clock() - start) / len(engines)


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("other", type=Path)
    parser.add_argument("--rounds", type=int, default=15)
    known, rest = parser.parse_known_args(argv)
    engines, shared = _states(rest or DEFAULT)
    other = _other(known.other)
    mine = snapshot.Snapshots(shared)
    theirs = other.Snapshots(shared)
    times: dict[str, list[tuple[float, float]]] = {"this": [], "other": []}
    for _ in range(known.rounds):
        times["this"].append(_round(mine, engines))
        times["other"].append(_round(theirs, engines))
    print(f"{len(engines)} states, {known.rounds} rounds; us a copy: fastest round / median round")
    print("| code | dump | load | dump + load |")
    print("|---|---|---|---|")
    for name, rounds in times.items():
        dumps, loads = [r[0] * 1e6 for r in rounds], [r[1] * 1e6 for r in rounds]
        both = [d + lo for d, lo in zip(dumps, loads, strict=True)]
        print(f"| {name} | {min(dumps):.0f} / {statistics.median(dumps):.0f} "
              f"| {min(loads):.0f} / {statistics.median(loads):.0f} "
              f"| {min(both):.0f} / {statistics.median(both):.0f} |")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
