"""The sim world refuses non-finite numbers, names default outputs by radio settings, and reports a
video or picture it could not write."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from pydantic import ValidationError

from hfsm.cli.run import main
from hfsm_behaviours.world import default_stem
from hfsm_sim.recorder import Recorder
from hfsm_sim.scenario import scenario_from_dict

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


def scenario_errors(capsys: pytest.CaptureFixture[str], tmp_path: Path, text: str) -> list[str]:
    """A run of the paper's machine on a scenario file of `text`: exit 2, no traceback, and its
    errors, each from the line and column on."""
    scenario = tmp_path / "room.yaml"
    scenario.write_text(text)
    code = main([str(ROOT / "machines" / "move_furniture.yaml"), "--scenario", str(scenario), "--no-video"])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    return [line.split("room.yaml:")[1] for line in err.splitlines() if "room.yaml:" in line]


def test_a_scenarios_numbers_out_of_range_are_exit_2_with_value_and_range_all_at_once(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    assert scenario_errors(capsys, tmp_path, (
        "robots:\n  r1: {x: 1, y: 1, speed: 0}\n  r2: {x: -1, y: -1, speed: 4}\n"
        "jitter: {position: -1}\nroom: {width: 60}\nbattery: {idle: 1.5}\n"
    )) == [
        "2:27: error[E200]: 'speed' must be > 0 and <= 3, not 0 (top speed, m/s (default: the body's))",
        "3:29: error[E200]: 'speed' must be > 0 and <= 3, not 4 (top speed, m/s (default: the body's))",
        "4:20: error[E200]: 'position' must be >= 0 and <= 1, not -1 (max offset per axis, metres)",
        "5:15: error[E200]: 'width' must be > 1.5 and <= 50, not 60 (extent along x, metres)",
        "6:17: error[E200]: 'idle' must be >= 0 and <= 1, not 1.5 (charge spent per second)",
    ]


def test_a_scenarios_room_checks_are_exit_2_at_each_value_all_at_once(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    assert scenario_errors(capsys, tmp_path, (
        "table: {x: 9}\ntargets:\n  - {id: table1, x: 7, y: 0}\n"
        "robots:\n  r1: {x: 2.4, y: 0}\n  r2: {x: 0, y: -9}\njitter: {position: 0.1}\n"
    )) == [
        "1:12: error[E200]: 'x' must be from -2.1 to 2.1 for the table (0.8 x 0.5 m, yaw 0) to fit inside "
        "the room (5 x 5 m), not 9",
        "3:10: error[E200]: task id 'table1' is used before: ids must be unique across tables and targets",
        "3:21: error[E200]: 'x' must be from -2.5 to 2.5 inside the room (5 x 5 m), not 7",
        "5:11: error[E200]: 'x' must be from -2.2 to 2.2 for the robot to start inside the room (5 x 5 m) "
        "0.2 m from its walls, with 0.1 m of jitter, not 2.4",
        "6:17: error[E200]: 'y' must be from -2.2 to 2.2 for the robot to start inside the room (5 x 5 m) "
        "0.2 m from its walls, with 0.1 m of jitter, not -9",
    ]
