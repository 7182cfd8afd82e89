"""The run's video plays in a browser: the monitor's page loads it and reports its duration."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.monitor import read_trace
from hfsm.cli.run import main as run_main
from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_the_h264_video_of_a_sim_run_plays_in_chromium(page: Any, tmp_path: Path) -> None:
    code = run_main([str(ROOT / "machines" / "move_furniture.yaml"), "--max-time", "4", "--out", str(tmp_path),
                     "--quiet", "--progress", "0"])
    assert code == 1  # stopped by --max-time, with the video and the trace written
    trace = tmp_path / "opposite_long_side-seed0.jsonl"
    server = Server(Hub(read_trace(trace)), {}, trace.name, video=trace.with_suffix(".mp4"))
    server.start()
    try:
        page.goto(server.url)
        page.wait_for_function("document.getElementById('video').readyState >= 1", timeout=20000)
        assert page.evaluate("document.getElementById('video').duration") == pytest.approx(0.9)  # 9 frames, 10 fps
        assert page.evaluate("document.getElementById('video').videoWidth") == 480
        page.evaluate("window.hfsm.seek(2)")  # the room from above, drawn from the trace's poses
        assert page.inner_text("#room-note") == ""
        assert page.locator(".agent").count() == 2
    finally:
        server.stop()
