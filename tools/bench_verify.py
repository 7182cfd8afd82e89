"""States a second of hfsm-verify on the paper's two-robot handshakes, with stand-ins, and where the
time goes (keys of states, copying states in and out as bytes, running the engine's ticks).

Rewrites the bench_verify section of docs/VERIFY.md (bench_verify_values with --keys values; nothing
else in it).
Usage: nice -n 15 .venv/bin/python tools/bench_verify.py [--no-doc] [--runs N] [--keys bytes|values]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from hfsm.verify import canon, search, snapshot

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
M = ROOT / "machines"
PAIR = ["--agents", "r1,r2"]
ROLES = ["--agent-param", "r1:role=leader", "--agent-param", "r2:role=assistant"]
CASES: list[tuple[str, list[str]]] = [
    ("elect_leader, --loss 1 --fail 1", [str(M / "elect_leader.yaml"), *PAIR, "--param", "distance=1",
                                         "--param", "limit=5", "--loss", "1", "--fail", "1"]),
    ("synchronised_lift_table (lift_table a stand-in), --loss 1",
     [str(M / "synchronised_lift_table.yaml"), *PAIR, *ROLES, "--param", "patience=5", "--loss", "1"]),
    ("synchronised_lift_table (lift_table a stand-in), --loss 1 --fail 1",
     [str(M / "synchronised_lift_table.yaml"), *PAIR, *ROLES, "--param", "patience=5", "--loss", "1",
      "--fail", "1"]),
    ("call_off, --loss 1 --fail 1", [str(M / "call_off.yaml"), *PAIR, "--param", "cycle=1", "--loss", "1",
                                     "--fail", "1"]),
    ("move_furniture, --loss 1 --fail 1, its first 3,000 states",
     [str(M / "move_furniture.yaml"), *PAIR, "--loss", "1", "--fail", "1", "--max-states", "3000"]),
]  # fmt: skip


class Timed:
    """Seconds spent in a function, added up (it replaces it while the bench runs)."""

    def __init__(self, owner: Any, name: str) -> None:
        self.owner, self.name, self.seconds = owner, name, 0.0
        self.original: Callable[..., Any] = getattr(owner, name)

    def __enter__(self) -> Timed:
        original = self.original

        def timed(*args: Any) -> Any:
            start = time.perf_counter()
            try:
                return original(*args)
            finally:
                self.seconds += time.perf_counter() - start

        setattr(self.owner, self.name, timed)
        return self

    def __exit__(self, *exc: object) -> None:
        setattr(self.owner, self.name, self.original)


def one(args: list[str]) -> dict[str, Any]:
    import contextlib
    import io
    import json
    import tempfile
    from unittest import mock

    from hfsm.cli import verify as verify_cli

    searched = [0.0]
    explore = search.explore

    def timed_explore(*args: Any) -> Any:
        start = time.process_time()
        try:
            return explore(*args)
        finally:
            searched[0] += time.process_time() - start

    with (
        mock.patch.object(search, "explore", timed_explore),
        tempfile.TemporaryDirectory() as folder,
        Timed(snapshot.Snapshots, "dump") as dump,
        Timed(snapshot.Snapshots, "load") as load,
        Timed(canon.Keys, "__call__") as digest,
    ):
        out = io.StringIO()
        cpu = time.process_time()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = verify_cli.main([*args, "--json", "--out", str(Path(folder) / "ce.jsonl")])
        cpu = time.process_time() - cpu
    verdict: dict[str, Any] = json.loads(out.getvalue())
    verdict.update(
        code=code, dump=dump.seconds, load=load.seconds, key=digest.seconds, cpu=cpu, search_cpu=searched[0]
    )
    return verdict


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-doc", action="store_true", help="print only; leave docs/VERIFY.md")
    parser.add_argument("--runs", type=int, default=5, help="runs of each case (medians are shown)")
    parser.add_argument("--keys", choices=("bytes", "values"), default="bytes", help="hfsm-verify's --keys")
    args = parser.parse_args()
    rows = []
    for name, case in CASES:
        runs = [one([*case, "--keys", args.keys]) for _ in range(args.runs)]
        v = runs[0]
        spent = statistics.median(r["seconds"] or 1e-9 for r in runs)
        rate = statistics.median(r["states"] / (r["search_cpu"] or 1e-9) for r in runs)
        cpu = statistics.median(r["search_cpu"] for r in runs)
        rates = ", ".join(f"{r['states'] / (r['search_cpu'] or 1e-9):,.0f}" for r in runs)
        share = {
            k: statistics.median(r[k] / (r["seconds"] or 1e-9) for r in runs) for k in ("key", "dump", "load")
        }
        rest = 1 - sum(share.values())
        rows.append(
            f"| {name} | {v['verdict']} | {v['states']} | {spent:.2f} | {v['states'] / spent:,.0f} "
            f"| {cpu:.2f} | **{rate:,.0f}** ({rates}) "
            f"| {100 * share['key']:.0f} % | {100 * (share['dump'] + share['load']):.0f} % "
            f"| {100 * rest:.0f} % |"
        )
        print(rows[-1], flush=True)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    lines = [
        "",
        f"`nice -n 15 .venv/bin/python tools/bench_verify.py --keys {args.keys}` on "
        f"{platform.python_implementation()} {platform.python_version()}, {os.cpu_count()} cores, "
        f"load average {load:.1f} when it ended:",
        "",
        "| case | verdict | states | seconds (median) | states/s | CPU-s of the search (median) "
        "| states/CPU-s of the search: median (each run) "
        "| keys | copies | engine and search |",
        "|---|---|---|---|---|---|---|---|---|---|",
        *rows,
        "",
    ]
    if not args.no_doc:
        section = "bench_verify" if args.keys == "bytes" else "bench_verify_values"
        write_section(ROOT / "docs" / "VERIFY.md", section, lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
