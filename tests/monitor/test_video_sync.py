"""The run's video tied to the timeline, in headless Chromium: the timeline seeks the video, seeking
or playing the video moves the timeline; a live run's video shows once the world has written it."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server
from hfsm_sim.video import VideoWriter

RATE = 5.0  # simulated seconds a second of video shows (a frame each 0.5 s at 10 fps)
RECORDS = [{"t": 0.0, "agent": "robot", "path": ["m"], "kind": "enter"}] + [
    {"t": round(0.5 * k, 9), "agent": "robot", "path": ["m", f"s{k}"], "kind": "enter", "do": "wait"}
    for k in range(21)
]


@pytest.fixture
def video(tmp_path: Path) -> Path:
    """21 frames at 10 fps (2.1 s): a run of 10 s filmed every 0.5 s, each frame a different grey."""
    path = tmp_path / "run.mp4"
    writer = VideoWriter(path, 10)
    for k in range(21):
        writer.write(np.full((64, 64, 3), k * 12, np.uint8))
    writer.close()
    return path


@pytest.fixture
def served(video: Path) -> Iterator[Server]:
    server = Server(Hub(RECORDS), {}, "run.jsonl", video=video, video_rate=RATE)
    server.start()
    yield server
    server.stop()


def _loaded(page: Any) -> None:
    page.wait_for_function("document.getElementById('video').readyState >= 1", timeout=20000)


def _page_time(page: Any) -> float:
    return float(page.evaluate("window.hfsm.page.time"))


def test_the_timeline_seeks_the_video(page: Any, served: Server) -> None:
    page.goto(served.url)
    _loaded(page)
    page.evaluate("window.hfsm.seek(5)")
    page.wait_for_function("Math.abs(document.getElementById('video').currentTime - 1.0) < 1e-3")
    page.click("#step")  # the next tick with records: 5.5 s
    page.wait_for_function("Math.abs(document.getElementById('video').currentTime - 1.1) < 1e-3")
    page.evaluate("window.hfsm.seek(0)")
    page.wait_for_function("document.getElementById('video').currentTime === 0")


def test_seeking_and_playing_the_video_moves_the_timeline(page: Any, served: Server) -> None:
    page.goto(served.url)
    _loaded(page)
    page.evaluate("document.getElementById('video').currentTime = 1.5")  # as its own slider does
    page.wait_for_function("Math.abs(window.hfsm.page.time - 7.5) < 1e-6")
    assert page.inner_text("#time") == "7.50 s"
    assert not page.evaluate("document.getElementById('follow').checked")
    page.evaluate("document.getElementById('video').play()")
    page.wait_for_function("window.hfsm.page.time > 8", timeout=20000)
    page.wait_for_function("document.getElementById('video').ended", timeout=20000)
    assert _page_time(page) == pytest.approx(10.0, abs=0.01)  # the video's end is the run's
    assert "s20 (wait)" in page.inner_text(".agent")  # the page shows the run at the video's end


def test_a_live_run_shows_its_video_once_written(page: Any, video: Path) -> None:
    hub = Hub(live=True)
    hub.video_ready = False  # as LiveMonitor: the world writes the video when it closes
    for record in RECORDS[:3]:
        hub.offer(record)
    server = Server(hub, {}, "m", video=video, video_rate=RATE)
    server.start()
    try:
        page.goto(server.url)
        page.wait_for_function("window.hfsm.replay.records.length === 3")
        assert page.locator("#video-box").is_hidden()
        base = server.url.split("?")[0]
        assert page.request.get(base + "video").status == 404  # not while it is being written
        assert json.loads(page.request.get(base + "api/meta").text())["video_pending"] is True
        hub.offer(None)  # the run ends ...
        page.wait_for_function("document.getElementById('status').textContent.includes('ended')")
        assert page.locator("#video-box").is_hidden()
        hub.video_ready = True  # ... and the world has closed its video
        page.wait_for_selector("#video-box", state="visible", timeout=20000)
        _loaded(page)
        meta = json.loads(page.request.get(base + "api/meta").text())
        assert (meta["video"], meta["video_pending"]) == ({"src": "/video", "rate": RATE}, False)
    finally:
        server.stop()
