"""Where robot-robot contacts happen: rooms drawn by the generator run as the bench runs them, each
contact the scorer counts (a new episode of two robots touching) recorded with its time and what
both robots were doing then (the behaviours they ran, deepest first), and classified.

    nice -n 5 .venv/bin/python tools/room_contacts.py --strata open,close --seeds 100-103 \
        --workers 2 --max-time 900 --out out/contacts.jsonl
    .venv/bin/python tools/room_contacts.py --table out/contacts.jsonl

Development seeds only (below 10000, tools/room/experiments.py). The scorer and the trace are
read here as an observer would: nothing the robots act on changes.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tools.room.contacts import census, classify  # noqa: E402
from tools.room_gen import seeds_of  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--strata", default="open,close,walls,narrow,crowded,failures,loss,mixed")
    p.add_argument("--seeds", default="100")
    p.add_argument("--workers", type=int, default=1)
    p.add_argument("--max-time", type=float, default=900.0)
    p.add_argument("--out", type=Path, default=Path("out/contacts.jsonl"))
    p.add_argument("--table", type=Path, help="print the classification of a census file and stop")
    args = p.parse_args(argv)
    if args.table:
        lines = args.table.read_text(encoding="utf-8").splitlines()
        print_table([json.loads(line) for line in lines if line])
        return 0
    jobs = [(s, seed, args.max_time) for seed in seeds_of(args.seeds) for s in args.strata.split(",") if s]
    args.out.parent.mkdir(parents=True, exist_ok=True)
    rooms: list[dict[str, Any]] = []
    with ProcessPoolExecutor(max_workers=args.workers) as pool, args.out.open("a", encoding="utf-8") as out:
        for room in pool.map(_census, jobs):
            rooms.append(room)
            out.write(json.dumps(room, sort_keys=True) + "\n")
            out.flush()
            print(f"{room['stratum']}-{room['seed']}: success {room['success']}, "
                  f"{len(room['contacts'])} contacts, {room['sim']} s sim, {room['wall']} s wall",
                  file=sys.stderr, flush=True)
    print_table(rooms)
    return 0


def _census(job: tuple[str, int, float]) -> dict[str, Any]:
    stratum, seed, max_time = job
    return census(stratum, seed, max_time)


def print_table(rooms: list[dict[str, Any]]) -> None:
    kinds: Counter[str] = Counter()
    for room in rooms:
        for c in room["contacts"]:
            kinds[classify(c["a_doing"], c["a_failed"]) + " / " + classify(c["b_doing"], c["b_failed"])] += 1
    total = sum(len(r["contacts"]) for r in rooms)
    print(f"{len(rooms)} rooms, {sum(r['success'] for r in rooms)} successes, {total} contacts")
    print("| robot a / robot b (sorted) | contacts |\n|---|---|")
    for kind, n in kinds.most_common():
        print(f"| {kind} | {n} |")


if __name__ == "__main__":
    sys.exit(main())
