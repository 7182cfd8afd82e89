"""States a second of hfsm-verify on the paper's two-robot handshakes, with stand-ins, and where the
time goes (copying states in and out as bytes, against running the engine's ticks).

Rewrites the bench_verify section of docs/VERIFY.md (nothing else in it).
Usage: nice -n 15 .venv/bin/python tools/bench_verify.py [--no-doc]
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from hfsm.verify import search, snapshot

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

    from hfsm.cli import verify as verify_cli

    with (
        tempfile.TemporaryDirectory() as folder,
        Timed(snapshot.Snapshots, "dump") as dump,
        Timed(snapshot.Snapshots, "load") as load,
        Timed(search, "digest") as digest,
    ):
        out = io.StringIO()
        cpu = time.process_time()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = verify_cli.main([*args, "--json", "--out", str(Path(folder) / "ce.jsonl")])
        cpu = time.process_time() - cpu
    verdict: dict[str, Any] = json.loads(out.getvalue())
    verdict.update(code=code, dump=dump.seconds, load=load.seconds, digest=digest.seconds, cpu=cpu)
    return verdict


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--no-doc", action="store_true", help="print only; leave docs/VERIFY.md")
    args = parser.parse_args()
    rows = []
    for name, case in CASES:
        v = one(case)
        spent = v["seconds"] or 1e-9
        copy = v["dump"] + v["load"] + v["digest"]
        rows.append(
            f"| {name} | {v['verdict']} | {v['states']} | {v['seconds']:.2f} | {v['states'] / spent:,.0f} "
            f"| {v['states'] / v['cpu']:,.0f} "
            f"| {100 * copy / spent:.0f} % | {100 * (spent - copy) / spent:.0f} % |"
        )
        print(rows[-1], flush=True)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    lines = [
        "",
        f"`nice -n 15 .venv/bin/python tools/bench_verify.py` on {platform.python_implementation()} "
        f"{platform.python_version()}, {os.cpu_count()} cores, load average {load:.1f} when it ended:",
        "",
        "| case | verdict | states | seconds | states/s | states/CPU-s (process, load, checks included) "
        "| copying states | engine and search |",
        "|---|---|---|---|---|---|---|---|",
        *rows,
        "",
    ]
    if not args.no_doc:
        write_section(ROOT / "docs" / "VERIFY.md", "bench_verify", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
