from __future__ import annotations

from pathlib import Path

import cv2

from hfsm_sim.recorder import Recorder
from hfsm_sim.scenario import load_scenario
from hfsm_sim.world import World


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


def _video(path: Path) -> tuple[str, int, float]:
    import av

    with av.open(str(path)) as container:
        stream = container.streams.video[0]
        frames = sum(1 for _ in container.decode(stream))
        return stream.codec_context.name, frames, float(container.duration or 0) / 1e6


def test_mp4_is_h264_and_webm_is_vp9_that_browsers_play(tmp_path: Path) -> None:
    for name, codec in (("run.mp4", "h264"), ("run.webm", "vp9")):
        recorder = Recorder(tmp_path / name, every=0.5, size=120, fps=2.0)
        with World(load_scenario(), 0, recorder=recorder) as world:
            world.advance(2.0)
        assert _video(tmp_path / name) == (codec, 5, 2.5)


def test_3d_view_is_a_lit_perspective_with_labels(tmp_path: Path) -> None:
    recorder = Recorder(tmp_path / "run.mp4", every=1.0, size=240, view="3d")
    with World(load_scenario(), 0, recorder=recorder) as world:
        world.labels["r1"] = "leader: go_to_table"
        world.advance(1.0)
    png = cv2.imread(str(tmp_path / "run.png"))
    assert png is not None and png.shape[:2] == (240, 320)
    floor = png[200:230, 100:220].reshape(-1, 3)
    assert floor.std(axis=0).max() > 1.0  # shaded, not one flat colour
    assert _video(tmp_path / "run.mp4")[:2] == ("h264", 2)
