"""Where a state's microseconds go in hfsm-verify: the CPU time of each part of the search (the
tick, dumping a state to bytes, loading a copy back, hashing, the rest), per state and per call.

Each part is timed with the thread's CPU clock around it, so other processes on the machine count
for little. Prints a table; nothing is written.
Usage: nice -n 15 .venv/bin/python tools/profile_verify.py [hfsm-verify arguments]
(default: machines/move_furniture.yaml --agents r1,r2 --loss 1 --fail 1 --max-states 3000)
"""

from __future__ import annotations

import contextlib
import io
import json
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from hfsm.cli import verify as verify_cli
from hfsm.verify import search, snapshot, step

ROOT = Path(__file__).resolve().parent.parent
DEFAULT = [str(ROOT / "machines" / "move_furniture.yaml"), "--agents", "r1,r2", "--loss", "1", "--fail", "1",
           "--max-states", "3000"]  # fmt: skip


class Part:
    """CPU seconds and calls of one function while the search runs (it replaces it meanwhile)."""

    def __init__(self, owner: Any, name: str) -> None:
        self.owner, self.name = owner, name
        self.original: Callable[..., Any] = getattr(owner, name)
        self.seconds, self.calls = 0.0, 0

    def __enter__(self) -> Part:
        original, clock = self.original, time.thread_time

        def timed(*args: Any) -> Any:
            start = clock()
            try:
                return original(*args)
            finally:
                self.seconds += clock() - start
                self.calls += 1

        setattr(self.owner, self.name, timed)
        return self

    def __exit__(self, *exc: object) -> None:
        setattr(self.owner, self.name, self.original)


def main(argv: list[str]) -> int:
    args = argv or DEFAULT
    with (
        tempfile.TemporaryDirectory() as folder,
        Part(search, "explore") as explore,
        Part(step, "next_state") as tick,
        Part(snapshot.Snapshots, "dump") as dump,
        Part(snapshot.Snapshots, "load") as load,
        Part(search, "digest") as digest,
    ):
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            verify_cli.main([*args, "--json", "--out", str(Path(folder) / "ce.jsonl")])
    verdict = json.loads(out.getvalue())
    states = verdict["states"]
    rest = explore.seconds - tick.seconds - dump.seconds - load.seconds - digest.seconds
    print(f"{' '.join(args)}\n{verdict['verdict']}, {states} states, {explore.seconds:.2f} CPU-s of search, "
          f"{states / explore.seconds:,.0f} states per CPU-second\n")  # fmt: skip
    print("| part | calls | CPU-s | share | us a state | us a call |")
    print("|---|---|---|---|---|---|")
    for name, part_s, calls in (
        ("tick (next_state)", tick.seconds, tick.calls),
        ("dump (copy to bytes)", dump.seconds, dump.calls),
        ("load (copy from bytes)", load.seconds, load.calls),
        ("hash of the bytes", digest.seconds, digest.calls),
        ("the rest (checks, queue, choices)", rest, 0),
    ):
        per_call = f"{1e6 * part_s / calls:,.0f}" if calls else ""
        print(f"| {name} | {calls or ''} | {part_s:.2f} | {100 * part_s / explore.seconds:.0f} % "
              f"| {1e6 * part_s / states:,.0f} | {per_call} |")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
