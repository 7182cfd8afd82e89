"""The `hfsm.worlds` entry point for `--world sim`.

Light on purpose: hfsm-run loads it for every run to learn the flags; the simulator (and
pybullet) is imported only when a sim world is made.
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from behaviours.inputs import SIM_INPUTS
from hfsm.errors import UsageError
from hfsm.world import InputSpec

if TYPE_CHECKING:
    from behaviours.simworld import SimWorld

DEFAULT_SCENARIO = "opposite_long_side"


class SimWorldFactory:
    name = "sim"

    def inputs(self) -> Mapping[str, InputSpec]:
        return SIM_INPUTS

    def add_arguments(self, group: argparse._ArgumentGroup) -> None:
        group.add_argument(
            "--scenario",
            default=DEFAULT_SCENARIO,
            metavar="NAME|FILE",
            help=f"a shipped scenario or a scenario file (default {DEFAULT_SCENARIO})",
        )
        group.add_argument(
            "--out",
            type=Path,
            default=Path("out"),
            metavar="DIR",
            help="where the trace, video and final picture go by default (default out/)",
        )
        group.add_argument(
            "--video",
            type=Path,
            metavar="FILE",
            help="video, .mp4 (H.264), .webm (VP9) or .gif (default DIR/SCENARIO-seedN.mp4)",
        )
        group.add_argument(
            "--view",
            choices=("top", "3d"),
            default="top",
            help="the video and final picture: a schematic from above (fast, default) or a lit 3-D view",
        )
        group.add_argument("--no-video", action="store_true", help="no video and no final picture")
        group.add_argument("--image-size", default="160x120", metavar="WxH", help="camera images")
        group.add_argument("--radio-latency", type=float, default=0.1, metavar="S")
        group.add_argument("--radio-loss", type=float, default=0.0, metavar="P")
        group.add_argument(
            "--progress",
            type=float,
            default=60.0,
            metavar="S",
            help="print the simulated time every S seconds (0: never; default 60)",
        )

    def create(self, args: argparse.Namespace, seed: int) -> SimWorld:
        from behaviours.simworld import SimWorld, load_scenario
        from sim import World
        from sim.recorder import Recorder

        scenario, name = load_scenario(args.scenario)
        size = _image_size(args.image_size)
        if not 0 <= args.radio_loss <= 1 or args.radio_latency < 0:
            raise UsageError("--radio-loss takes 0..1 and --radio-latency a number >= 0")
        stem = args.out / f"{name}-seed{seed}"
        video = None if args.no_video else args.video or stem.with_suffix(".mp4")
        recorder = None
        if video is not None:
            writable_folder(video.parent, "--video")
            recorder = Recorder(video, view=args.view)
        world = World(
            scenario,
            seed,
            image_size=size,
            radio_latency=args.radio_latency,
            radio_loss=args.radio_loss,
            recorder=recorder,
        )
        outputs = [video, video.with_suffix(".png")] if video else []
        trace = stem.with_suffix(".jsonl")
        return SimWorld(world, progress_every=args.progress, outputs=outputs, default_trace=trace)


def writable_folder(folder: Path, flag: str) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UsageError(f"{flag}: cannot write in {folder}: {exc.strerror or exc}") from None


def _image_size(text: str) -> tuple[int, int]:
    width, sep, height = text.partition("x")
    if not (sep and width.isdigit() and height.isdigit() and int(width) >= 16 and int(height) >= 12):
        raise UsageError(f"--image-size {text!r}: write WIDTHxHEIGHT, e.g. 160x120")
    return int(width), int(height)
