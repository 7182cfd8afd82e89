"""Runs hfsm-verify's corpus (tests/verify/data/corpus.yaml) as a user would, one process a run, and
prints each run's verdict against the one expected, its CPU and wall seconds, and for a planted bug
whether its counterexample replays byte for byte. Exit 1 when any verdict is wrong, any run takes
more than --limit CPU-seconds, or any replay differs.
Usage: nice -n 15 .venv/bin/python tools/verify_corpus.py [--limit 120] [MACHINE…]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "verify" / "data"
BIN = Path(sys.executable).parent


def _cpu() -> float:
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def _args(args: list[str]) -> list[str]:
    return [str(DATA / a) if a.endswith(".yaml") else a for a in args]


def run(case: dict[str, Any], args: list[str], kind: str | None, folder: Path) -> tuple[bool, str]:
    file = DATA / f"{case['machine']}.yaml"
    out = folder / "ce.jsonl"
    out.unlink(missing_ok=True)
    cpu, wall = _cpu(), time.perf_counter()
    done = subprocess.run(
        [str(BIN / "hfsm-verify"), str(file), *args, "--json", "--out", str(out)],
        capture_output=True,
        text=True,
    )
    cpu, wall = _cpu() - cpu, time.perf_counter() - wall
    try:
        verdict = json.loads(done.stdout)
    except json.JSONDecodeError:
        verdict = {}
    if kind is None:
        right = done.returncode == 0 and verdict.get("exhausted") is True
    else:
        right = done.returncode == 1 and verdict.get("kind") == kind
    replayed = ""
    if kind is not None and done.returncode == 1:
        again = folder / "again.jsonl"
        subprocess.run(
            [
                str(BIN / "hfsm-run"),
                str(file),
                "--world",
                "none",
                "--replay",
                str(out),
                "--trace",
                str(again),
                "--quiet",
            ],
            capture_output=True,
        )
        same = again.exists() and again.read_bytes() == out.read_bytes()
        replayed = "same bytes" if same else "REPLAY DIFFERS"
        right = right and same
    found = verdict.get("kind") or verdict.get("verdict")
    flags = " ".join(Path(a).name if a.endswith(".yaml") else a for a in args)
    states = verdict.get("states")
    line = (
        f"| {case['machine']} | {flags} | {kind or 'ok'} | {done.returncode} {found} | {states} "
        f"| {cpu:.1f} | {wall:.1f} | {replayed} | {'yes' if right else '**NO**'} |"
    )
    return right, line


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("machines", nargs="*", help="only these (default: all)")
    parser.add_argument("--limit", type=float, default=120.0, help="CPU-seconds a run may take")
    args = parser.parse_args()
    corpus = yaml.safe_load((DATA / "corpus.yaml").read_text())
    print("| machine | flags | expected | exit, found | states | CPU-s | wall s | replay | right |")
    print("|---|---|---|---|---|---|---|---|---|")
    wrong = 0
    started = _cpu()
    with tempfile.TemporaryDirectory() as folder:
        runs = [(c, _args(c["args"]), None) for c in corpus["correct"]]
        for c in corpus["buggy"]:
            runs += [(c, _args(c["args"]), None), (c, _args([*c["args"], *c["trigger"]]), c["kind"])]
        for case, flags, kind in runs:
            if args.machines and case["machine"] not in args.machines:
                continue
            before = _cpu()
            right, line = run(case, flags, kind, Path(folder))
            right = right and _cpu() - before <= args.limit
            wrong += not right
            print(line, flush=True)
    print(f"\n{wrong} wrong; {_cpu() - started:.1f} CPU-s in all")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
