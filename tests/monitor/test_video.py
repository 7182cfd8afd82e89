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


@pytest.mark.slow
def test_a_live_sim_run_shows_its_video_once_the_world_wrote_it(page: Any, tmp_path: Path) -> None:
    import socket
    import subprocess
    import sys

    with socket.socket() as free:  # a port of our own: the simulator may quiet stderr while it starts
        free.bind(("127.0.0.1", 0))
        port = free.getsockname()[1]
    process = subprocess.Popen(
        [sys.executable, "-m", "hfsm.cli.run", str(ROOT / "machines" / "move_furniture.yaml"), "--max-time", "2",
         "--out", str(tmp_path), "--quiet", "--progress", "0", "--realtime", "2", "--monitor", str(port),
         "--monitor-hold", "30"],
        stderr=subprocess.DEVNULL, stdout=subprocess.DEVNULL)  # fmt: skip
    try:
        url = f"http://127.0.0.1:{port}/"
        for _ in range(600):
            try:
                page.goto(url)
                break
            except Exception:  # not serving yet
                assert process.poll() is None, "hfsm-run ended without serving the monitor"
                page.wait_for_timeout(100)
        page.wait_for_function("window.hfsm.replay.records.length > 0", timeout=60000)
        page.wait_for_selector("#video-box", state="visible", timeout=120000)
        page.wait_for_function("document.getElementById('video').readyState >= 1", timeout=20000)
        assert page.evaluate("document.getElementById('video').duration") == pytest.approx(0.5)  # 5 frames
        page.evaluate("window.hfsm.seek(1.5)")
        page.wait_for_function("Math.abs(document.getElementById('video').currentTime - 0.3) < 1e-3")
    finally:
        process.kill()
        process.wait()
