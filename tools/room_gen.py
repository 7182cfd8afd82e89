"""Write rooms drawn by the generator (hfsm_sim.roomgen) as scenario files, one per stratum and seed.

    .venv/bin/python tools/room_gen.py --seeds 1-3 --out out/rooms            # every stratum
    .venv/bin/python tools/room_gen.py --strata walls,close --seeds 7 --out out/rooms
    hfsm-run machines/clear_room.yaml --scenario out/rooms/walls-7.yaml --seed 0 --json --no-video
"""

from __future__ import annotations

import argparse
import difflib
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_sim.roomgen import STRATA, draw, write  # noqa: E402


def seeds_of(text: str) -> list[int]:
    """`3`, `1-5` or `1,4,9-11` as seeds."""
    out: list[int] = []
    for part in text.split(","):
        first, _, last = part.partition("-")
        out += list(range(int(first), int(last or first) + 1))
    return out


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--strata", default=",".join(STRATA), help="comma-separated (default: all)")
    p.add_argument("--seeds", default="1", help="seeds: 3, 1-5 or 1,4,9-11")
    p.add_argument("--out", type=Path, default=Path("out/rooms"))
    args = p.parse_args(argv)
    strata = [s for s in args.strata.split(",") if s]
    for s in strata:
        if s not in STRATA:
            close = difflib.get_close_matches(s, STRATA, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            print(f"room_gen: unknown stratum {s!r}{hint} (strata: {', '.join(STRATA)})", file=sys.stderr)
            return 2
    try:
        seeds = seeds_of(args.seeds)
    except ValueError:
        print(f"room_gen: --seeds takes 3, 1-5 or 1,4,9-11, not {args.seeds!r}", file=sys.stderr)
        return 2
    for s in strata:
        for seed in seeds:
            path = args.out / f"{s}-{seed}.yaml"
            write(path, draw(seed, s))
            print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
