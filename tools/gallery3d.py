"""3-D pictures for docs/: each of the paper's six starts, and the table at the wall at the end of a
run; and what `--view 3d` costs per simulated minute against the schematic view.

    .venv/bin/python tools/gallery3d.py                 # writes docs/figures/3d/*.png
    .venv/bin/python tools/gallery3d.py --report docs/PERFORMANCE.md
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from hfsm_sim.recorder import Recorder  # noqa: E402
from hfsm_sim.scenario import load_scenario  # noqa: E402
from hfsm_sim.world import World  # noqa: E402
from tools.docsection import write_section  # noqa: E402
from tools.paper.reference import SCENARIOS  # noqa: E402

HFSM_RUN = str(Path(sys.executable).parent / "hfsm-run")


def starts(out: Path) -> None:
    for name, _ in SCENARIOS:
        recorder = Recorder(out / f"{name}-start.mp4", view="3d")
        with World(load_scenario(name), 0, recorder=recorder):
            pass
        (out / f"{name}-start.mp4").unlink()


def whole_run(scenario: str, view: str, folder: Path) -> float:
    """Run the task in `view`; the wall time of the run."""
    video = folder / f"{scenario}-{view}.mp4"
    begin = time.perf_counter()
    command = [HFSM_RUN, str(ROOT / "machines" / "move_furniture.yaml"), "--scenario", scenario,
               "--view", view, "--video", str(video), "--out", str(folder), "--quiet", "--progress", "0"]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - begin


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", type=Path, default=ROOT / "docs" / "figures" / "3d")
    p.add_argument("--report", type=Path, help="also write the cost of --view 3d into this Markdown file")
    args = p.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    starts(args.out)
    scratch = ROOT / "out" / "gallery3d"
    scratch.mkdir(parents=True, exist_ok=True)
    walls = {view: whole_run("opposite_long_side", view, scratch) for view in ("top", "3d")}
    shutil.copy(scratch / "opposite_long_side-3d.png", args.out / "opposite_long_side-at-wall.png")
    trace = (scratch / "opposite_long_side-seed0.jsonl").read_text().splitlines()
    minutes = float(json.loads(trace[-1])["t"]) / 60
    extra = (walls["3d"] - walls["top"]) / minutes
    lines = [
        "Command: `.venv/bin/python tools/gallery3d.py --report docs/PERFORMANCE.md` (the task on",
        f"`opposite_long_side`, seed 0, {minutes:.1f} simulated minutes, a frame every 0.5 s).",
        "",
        "| view | wall time of the run |",
        "|---|---|",
        f"| `--view top` (schematic, default) | {walls['top']:.1f} s |",
        f"| `--view 3d` (640x480, lit) | {walls['3d']:.1f} s |",
        "",
        f"`--view 3d` costs **{extra:.1f} s of wall time per simulated minute** more than the schematic.",
    ]
    print("\n".join(lines))
    if args.report:
        write_section(args.report, "gallery3d", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
