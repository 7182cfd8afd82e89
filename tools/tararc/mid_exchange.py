"""A robot failing while TARARC's team shares, on a radio losing 30 % (docs/TARARC.md, "A robot
failing while the team shares"): `tests/machines/tararc.test.yaml`'s `four_robots_two_tasks`, r3
failing at each of 0 to 0.8 s, seeds 0 to N-1, world-free.

    nice -n 15 .venv/bin/python tools/tararc/mid_exchange.py --seeds 20 [--root /work/main]

`--root`: the checkout whose test cases and machines run (the interpreter's `hfsm` is its own).
A run goes wrong when a survivor does not end `done`, the survivors' first plans differ, or one
waits at `meet` past 5 s.
"""

from __future__ import annotations

import argparse
import statistics
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

ATS = (0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.8)


class Exits:
    """A trace sink keeping when each agent left each top-level state, and when each ended."""

    def __init__(self) -> None:
        self.left: dict[tuple[str, str], float] = {}
        self.ended: dict[str, float] = {}

    def write(self, record: dict[str, Any]) -> None:
        if record["kind"] == "exit" and len(record["path"]) == 2:
            self.left.setdefault((record["agent"], record["path"][1]), record["t"])
        if record["kind"] == "exit" and len(record["path"]) == 1:
            self.ended[record["agent"]] = record["t"]

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="a robot failing mid-exchange at 30 % loss")
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[2])
    args = parser.parse_args(argv)
    sys.path.insert(0, str(args.root / "tests"))
    from tararc_runs import case, run_plan  # the behaviour tests' lossy world

    from hfsm.testing.model import FailAt

    wrong, ends, messages = 0, [], 0
    for seed in range(args.seeds):
        for at in ATS:
            plan = case("tararc.test.yaml", "four_robots_two_tasks")
            plan = replace(plan, fail=[FailAt(agent="r3", at=at)])
            exits = Exits()
            result, lost = run_plan(plan, loss=0.3, seed=seed, trace=exits)
            messages += lost
            survivors = [a for a in result.agents if a != "r3"]
            firsts = [result.agents[a].outputs.get("first") for a in survivors]
            bad = (any(result.agents[a].outcome != "done" for a in survivors)
                   or any(f != firsts[0] for f in firsts)
                   or any(exits.left.get((a, "meet"), 0.0) > 5.1 for a in survivors))
            wrong += bad
            ends.append(max(exits.ended.get(a, 0.0) for a in survivors))
            if bad:
                print(f"seed {seed} r3@{at}: wrong: {[result.agents[a].outcome for a in survivors]}")
    runs = args.seeds * len(ATS)
    print(f"{wrong} of {runs} runs went wrong; last survivor ends at {statistics.median(ends):.2f} s median, "
          f"{max(ends):.2f} s at most; {messages} messages and notices lost")
    return 0


if __name__ == "__main__":
    sys.exit(main())
