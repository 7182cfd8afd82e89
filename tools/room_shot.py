"""The README's picture of a room being cleared: frames of a clear_room run's video side by side.

    .venv/bin/python tools/room_shot.py out/room_3_tables-seed0.mp4 docs/figures/room/room_3_tables.png

The video is what `hfsm-run machines/clear_room.yaml --scenario room_3_tables` writes (a frame every
0.5 simulated seconds); the picture shows it at the given seconds (default 0, 40, 80 and the end).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import cv2
import numpy as np

EVERY = 0.5  # simulated seconds between two frames (hfsm_sim.recorder's default)


def frames(video: Path, seconds: list[float]) -> list[np.ndarray]:
    cap = cv2.VideoCapture(str(video))
    count = int(cap.get(cv2.CAP_PROP_FRAME_COUNT))
    out = []
    for s in seconds:
        index = count - 1 if s < 0 else min(count - 1, round(s / EVERY))
        cap.set(cv2.CAP_PROP_POS_FRAMES, index)
        ok, frame = cap.read()
        if not ok:
            raise SystemExit(f"room_shot: no frame {index} in {video}")
        out.append(frame)
    cap.release()
    return out


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("video", type=Path)
    p.add_argument("picture", type=Path)
    p.add_argument("--at", default="0,40,80,-1", help="seconds, comma-separated (-1: the last frame)")
    args = p.parse_args(argv)
    shots = frames(args.video, [float(s) for s in args.at.split(",")])
    gap = np.full((shots[0].shape[0], 6, 3), 255, dtype=np.uint8)
    row = [shots[0]]
    for shot in shots[1:]:
        row += [gap, shot]
    args.picture.parent.mkdir(parents=True, exist_ok=True)
    cv2.imwrite(str(args.picture), np.hstack(row))
    print(f"wrote {args.picture}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
