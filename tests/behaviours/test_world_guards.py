"""The sim world refuses non-finite numbers, names default outputs by radio settings, and reports a
video or picture it could not write."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from behaviours.world import default_stem
from hfsm.cli.run import main
from sim.recorder import Recorder
from sim.scenario import scenario_from_dict

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize(
    "data",
    [
        {"robots": {"r1": {"x": 0.5, "y": 0.5, "yaw": float("nan")}}},
        {"robots": {"r1": {"x": float("nan"), "y": 0.5}}},
        {"robots": {"r1": {"x": 0.5, "y": 0.5}}, "table": {"x": float("inf")}},
    ],
)
def test_non_finite_scenario_numbers_are_refused(data: dict[str, object]) -> None:
    with pytest.raises(ValidationError, match="finite"):
        scenario_from_dict(data)


def test_a_nan_yaw_in_a_scenario_file_is_exit_2_at_its_position(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    scenario = tmp_path / "room.yaml"
    scenario.write_text("robots:\n  r1: {x: 1, y: 1, yaw: .nan}\n  r2: {x: -1, y: -1}\n")
    out_dir = tmp_path / "out"
    top = ROOT / "machines" / "move_furniture.yaml"
    code = main([str(top), "--scenario", str(scenario), "--out", str(out_dir)])
    err = capsys.readouterr().err
    assert code == 2 and "room.yaml:2:25: error[E100]: '.nan' is not a finite number" in err
    assert not out_dir.exists()


def test_default_names_differ_by_radio_settings() -> None:
    names = {default_stem("s", 0, loss, latency) for loss in (0.0, 0.1) for latency in (0.1, 2.0)}
    assert len(names) == 4 and default_stem("s", 0, 0.0, 0.1) == "s-seed0"
    assert default_stem("s", 3, 0.3, 2.0) == "s-seed3-loss0.3-latency2"


def test_a_video_that_cannot_be_written_is_an_os_error_at_close(tmp_path: Path) -> None:
    recorder = Recorder(tmp_path / "missing" / "v.mp4")
    recorder._write(np.zeros((48, 48, 3), np.uint8))
    recorder._write(np.zeros((48, 48, 3), np.uint8))
    with pytest.raises(OSError, match=r"cannot write .*v\.mp4 .*and .*v\.png"):
        recorder.close()


def test_a_video_of_an_unknown_kind_is_exit_2(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code = main([str(ROOT / "machines" / "move_furniture.yaml"), "--video", str(tmp_path / "v.avi")])
    err = capsys.readouterr().err
    assert code == 2 and "--video: a video is .mp4, .webm or .gif" in err and "Traceback" not in err


def test_a_written_video_and_picture_close_quietly(tmp_path: Path) -> None:
    recorder = Recorder(tmp_path / "v.mp4")
    for _ in range(3):
        recorder._write(np.zeros((48, 48, 3), np.uint8))
    recorder.close()
    assert (tmp_path / "v.mp4").stat().st_size > 0 and (tmp_path / "v.png").stat().st_size > 0
