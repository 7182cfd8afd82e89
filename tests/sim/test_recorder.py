from __future__ import annotations

from pathlib import Path

import cv2

from sim.recorder import Recorder
from sim.scenario import load_scenario
from sim.world import World


def test_mp4_and_final_png(tmp_path: Path) -> None:
    recorder = Recorder(tmp_path / "run.mp4", every=0.5, size=200, cameras=True)
    with World(load_scenario(), 0, image_size=(80, 60), recorder=recorder) as world:
        world.robots["r1"].set_velocity(0.1, 0.0, 0.3)
        world.advance(2.0)
    assert recorder.frames == 5
    assert (tmp_path / "run.mp4").stat().st_size > 1000
    png = cv2.imread(str(tmp_path / "run.png"))
    assert png is not None and png.shape[0] == 200 and png.shape[1] > 200


def test_gif(tmp_path: Path) -> None:
    recorder = Recorder(tmp_path / "run.gif", every=1.0, size=120)
    with World(load_scenario(), 0, recorder=recorder) as world:
        world.advance(2.0)
    assert recorder.frames == 3
    assert (tmp_path / "run.gif").stat().st_size > 0
    assert (tmp_path / "run.png").is_file()
