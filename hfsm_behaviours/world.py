"""The `hfsm.worlds` entry point for `--world sim`.

Light on purpose: hfsm-run loads it for every run to learn the flags; the simulator (and
pybullet) is imported only when a sim world is made.
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from hfsm.cli.guard import is_regular_or_new, make_folder, number
from hfsm.errors import UsageError
from hfsm.world import InputSpec
from hfsm_behaviours.inputs import SIM_INPUTS

if TYPE_CHECKING:
    from hfsm_behaviours.simworld import SimWorld

DEFAULT_SCENARIO = "opposite_long_side"


class SimWorldFactory:
    name = "sim"

    def inputs(self) -> Mapping[str, InputSpec]:
        return SIM_INPUTS

    def add_arguments(self, group: argparse._ArgumentGroup) -> None:
        group.add_argument(
            "--scenario",
            default=None,
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
        group.add_argument(
            "--image-size", type=_image_size, default=(160, 120), metavar="WxH",
            help="camera images, 16x12 to 1280x960 (default 160x120)",
        )
        group.add_argument("--radio-latency", type=LATENCY, default=0.1, metavar="S", help="0..3600 s")
        group.add_argument("--radio-loss", type=LOSS, default=0.0, metavar="P", help="0..1")
        group.add_argument(
            "--progress",
            type=PROGRESS,
            default=60.0,
            metavar="S",
            help="print the simulated time every S seconds (0: never; default 60)",
        )

    def check(self, args: argparse.Namespace) -> None:
        """`--check` with `--scenario`: the scenario is read and checked too (the simulator is
        imported only then; the default scenario ships checked)."""
        if args.scenario is not None:
            from hfsm_behaviours.simworld import load_scenario

            load_scenario(args.scenario)

    def create(self, args: argparse.Namespace, seed: int) -> SimWorld:
        from hfsm_behaviours.simworld import SimWorld, load_scenario
        from hfsm_sim import World
        from hfsm_sim.recorder import Recorder

        scenario, name = load_scenario(args.scenario or DEFAULT_SCENARIO)
        size = args.image_size
        stem = args.out / default_stem(name, seed, args.radio_loss, args.radio_latency)
        video = None if args.no_video else args.video or stem.with_suffix(".mp4")
        recorder = None
        if video is not None:
            if not is_regular_or_new(video):
                message = f"--video {video}: not a regular file (a video cannot report a failed write)"
                raise UsageError(message)
            make_folder(video.parent, "--video")
            try:
                recorder = Recorder(video, view=args.view)
            except ValueError as exc:
                raise UsageError(f"--video: {exc}") from None
        world = World(
            scenario,
            seed,
            image_size=size,
            radio_latency=args.radio_latency,
            radio_loss=args.radio_loss,
        )
        outputs = [video, video.with_suffix(".png")] if video else []
        trace = stem.with_suffix(".jsonl")
        return SimWorld(
            world, progress_every=args.progress, outputs=outputs, default_trace=trace, recorder=recorder
        )


def default_stem(name: str, seed: int, loss: float, latency: float) -> str:
    """SCENARIO-seedN, and the radio's settings when not the defaults: runs do not overwrite each other."""
    stem = f"{name}-seed{seed}"
    if loss:
        stem += f"-loss{loss:g}"
    if latency != DEFAULT_LATENCY:
        stem += f"-latency{latency:g}"
    return stem


LATENCY = number(0.0, 3600.0)
LOSS = number(0.0, 1.0)
PROGRESS = number(0.0, 1e9)
DEFAULT_LATENCY = 0.1
MAX_IMAGE = (1280, 960)


def _image_size(text: str) -> tuple[int, int]:
    width, sep, height = text.partition("x")
    if not (sep and width.isdigit() and height.isdigit()):
        raise argparse.ArgumentTypeError(f"{text!r}: write WIDTHxHEIGHT, e.g. 160x120")
    w, h = int(width), int(height)
    if not (16 <= w <= MAX_IMAGE[0] and 12 <= h <= MAX_IMAGE[1]):
        raise argparse.ArgumentTypeError(f"{text!r}: from 16x12 to {MAX_IMAGE[0]}x{MAX_IMAGE[1]}")
    return w, h
