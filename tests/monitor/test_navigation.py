"""Finding your way in the monitor's page (headless Chromium): the room's note, rounded numbers,
figures kept at the end, the breadcrumb, search and keys."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.monitor import drawings, read_trace
from hfsm.cli.run import main as run_main
from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server

ROOT = Path(__file__).resolve().parents[2]
PING_PONG = ROOT / "examples" / "ping_pong.yaml"
POSE = {"t": 0.5, "kind": "pose", "room": [6, 4], "tables": [], "targets": [], "robots": {"a": [0, 0, 0]}}


def _trace(tmp_path: Path) -> list[dict[str, Any]]:
    trace = tmp_path / "pp.jsonl"
    assert run_main([str(PING_PONG), "--agents", "a,b", "--trace", str(trace), "--quiet"]) == 0
    return read_trace(trace)


def _serve(records: list[dict[str, Any]]) -> Server:
    server = Server(Hub(records), drawings(PING_PONG, []), "pp.jsonl")
    server.start()
    return server


@pytest.fixture
def plain(tmp_path: Path) -> Iterator[Server]:
    server = _serve(_trace(tmp_path))
    yield server
    server.stop()


def _open(page: Any, url: str) -> None:
    page.goto(url)
    page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")


def test_no_poses_is_said_only_of_a_trace_without_any(page: Any, plain: Server, tmp_path: Path) -> None:
    _open(page, plain.url)
    assert page.inner_text("#room-note") == "No poses in this trace (a run without the simulator)."
    records = sorted([*_trace(tmp_path), POSE], key=lambda r: r["t"])
    server = _serve(records)
    try:
        _open(page, server.url)
        page.evaluate("window.hfsm.seek(0.1)")
        assert "No poses in this trace" not in page.inner_text("#room-note")
        assert "no pose recorded yet" in page.inner_text("#room-note")
        page.evaluate("window.hfsm.seek(0.6)")
        assert page.inner_text("#room-note") == ""
    finally:
        server.stop()


def test_vars_are_rounded_for_people(page: Any, tmp_path: Path) -> None:
    records = _trace(tmp_path)
    with_vars = next(r for r in records if r.get("vars"))
    with_vars["vars"] = {**with_vars["vars"], "x": 1 / 3, "big": 12345.678912, "deep": {"y": 2 / 3}}
    server = _serve(records)
    try:
        _open(page, server.url)
        page.evaluate(f"window.hfsm.seek({with_vars['t']})")
        table = page.inner_text(f'.agent[data-agent="{with_vars["agent"]}"] table.vars')
        assert "x\t0.333" in table and "0.3333" not in table
        assert "big\t12345.679" in table
        assert '{"y":0.667}' in table
    finally:
        server.stop()


def test_figures_stay_when_the_run_has_ended(page: Any, plain: Server) -> None:
    _open(page, plain.url)
    page.evaluate("window.hfsm.seek(1e9)")
    column = '.agent[data-agent="a"]'
    assert page.inner_text(f"{column} .result") == "ended in 'lost'"
    assert page.locator(f"{column}.ended .drawing").count() >= 1
    assert page.locator(f'{column} .drawing[data-machine="ping_pong"]').is_visible()
    assert page.eval_on_selector_all(f"{column} .drawing g.node.active title", "ns => ns.length") >= 1
    page.evaluate("window.hfsm.seek(0.05)")
    assert page.locator(f"{column}.ended").count() == 0


def _in_view(page: Any, selector: str) -> bool:
    return bool(
        page.evaluate(
            f"""(() => {{ const r = document.querySelector({selector!r}).getBoundingClientRect();
        return r.bottom > 0 && r.top < window.innerHeight; }})()"""
        )
    )


def test_the_breadcrumb_shows_the_active_path_and_scrolls_to_the_deepest_state(
    page: Any, plain: Server
) -> None:
    page.set_viewport_size({"width": 1400, "height": 200})
    _open(page, plain.url)
    page.evaluate("window.hfsm.seek(0.05)")
    crumbs = '.agent[data-agent="a"] .crumbs'
    assert page.inner_text(crumbs).replace("\n", "") == "ping_pong/receive"
    page.evaluate("window.scrollTo(0, 0)")
    page.click(f'{crumbs} button.crumb[data-path="ping_pong/receive"]')
    found = '.agent[data-agent="a"] .drawing g.node.found title'
    assert page.eval_on_selector_all(found, "ns => ns.map(n => n.textContent)") == ["receive"]
    assert _in_view(page, '.agent[data-agent="a"] .drawing g.node.found')


def test_search_lists_matching_states_and_scrolls_to_the_first(page: Any, plain: Server) -> None:
    page.set_viewport_size({"width": 1400, "height": 200})
    _open(page, plain.url)
    page.evaluate("window.hfsm.seek(0.05)")
    page.fill("#search", "RECEI")
    hits = page.eval_on_selector_all("#search-hits button.hit", "ns => ns.map(n => n.textContent)")
    assert hits == ["a: ping_pong/receive", "b: ping_pong/receive"]
    assert _in_view(page, ".drawing g.node.found")
    page.fill("#search", "nothing-like-it")
    assert "no state of that name" in page.inner_text("#search-hits")
    page.fill("#search", "<img src=x onerror=alert(1)>")
    assert page.locator("#search-hits img").count() == 0


def test_keys_play_pause_and_step_the_replay(page: Any, plain: Server) -> None:
    _open(page, plain.url)
    page.evaluate("window.hfsm.seek(0)")
    page.keyboard.press("ArrowRight")
    assert page.inner_text("#time") == "0.05 s"
    page.keyboard.press("ArrowRight")
    page.keyboard.press("ArrowLeft")
    assert page.inner_text("#time") == "0.05 s"
    page.keyboard.press(" ")
    assert page.evaluate("window.hfsm.page.playing")
    page.keyboard.press(" ")
    assert not page.evaluate("window.hfsm.page.playing")
    page.click("#step")  # a focused button: space still plays, not clicks it
    page.keyboard.press(" ")
    assert page.evaluate("window.hfsm.page.playing")
    page.keyboard.press(" ")
    assert not page.evaluate("window.hfsm.page.playing")
    at = page.inner_text("#time")
    page.fill("#search", "a b")  # keys typed in a field stay there: no play, no step
    assert page.inner_text("#time") == at and not page.evaluate("window.hfsm.page.playing")


def test_b_toggles_a_breakpoint_on_the_selected_state_of_a_live_run(page: Any, tmp_path: Path) -> None:
    machine = ROOT / "tests" / "monitor" / "data" / "operated.yaml"
    run = subprocess.Popen(
        [sys.executable, "-m", "hfsm.cli.run", str(machine), "--autonomy", "low", "--realtime", "1",
         "--monitor", "--monitor-hold", "0", "--quiet", "--trace", str(tmp_path / "o.jsonl")],
        stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True)  # fmt: skip
    try:
        assert run.stderr is not None
        line = ""
        while "monitor at" not in line:
            line = run.stderr.readline()
            assert line, "hfsm-run ended without serving the monitor"
        page.goto(line.split("monitor at ", 1)[1].strip())
        page.wait_for_function("!document.getElementById('operator').hidden")
        node = page.locator(".drawing g.node").filter(has=page.locator("title", has_text="listen")).first
        node.click()
        assert page.inner_text("#selected") == "selected: listen"
        page.keyboard.press("b")
        page.wait_for_function(
            "document.getElementById('op-breaks').textContent === 'breakpoints: enter:listen'"
        )
        page.keyboard.press("b")
        page.wait_for_function("document.getElementById('op-breaks').textContent === ''")
    finally:
        run.kill()
        run.wait()


def test_marks_on_the_timeline_and_jumps_between_them(page: Any, tmp_path: Path) -> None:
    extra = [
        {"t": 0.0, "kind": "operator", "do": "pause"},
        {
            "t": 0.15,
            "kind": "held",
            "agent": "a",
            "path": ["ping_pong", "receive"],
            "event": "<b>x</b>",
            "level": "high",
        },
        {"t": 0.15, "kind": "event", "agent": "b", "path": ["ping_pong", "receive"], "event": "timeout"},
    ]
    records = sorted([*_trace(tmp_path), *extra], key=lambda r: r["t"])
    sends = sorted({r["t"] for r in records if r["kind"] == "send"})
    server = _serve(records)
    try:
        _open(page, server.url)
        kinds = page.eval_on_selector_all("#marks .mark", "ns => ns.map(n => n.className)")
        assert kinds.count("mark message") == len([r for r in records if r["kind"] == "send"])
        assert {"mark operator", "mark hold", "mark timeout"} <= set(kinds)
        assert page.locator("#marks b").count() == 0
        times = sorted({0.0, 0.15, *sends})
        page.evaluate("window.hfsm.seek(0)")
        page.click("#next-mark")
        assert float(page.inner_text("#time").split()[0]) == pytest.approx(times[1])
        page.keyboard.press("n")
        assert float(page.inner_text("#time").split()[0]) == pytest.approx(times[2])
        page.keyboard.press("p")
        assert float(page.inner_text("#time").split()[0]) == pytest.approx(times[1])
        page.click("#prev-mark")
        assert page.inner_text("#time") == "0.00 s"
        page.locator("#marks .mark.hold").dispatch_event("click")  # it lies under the timeout's mark
        assert page.inner_text("#time") == "0.15 s"
    finally:
        server.stop()


def test_a_figure_opens_full_size_and_zooms_and_pans(page: Any, plain: Server) -> None:
    _open(page, plain.url)
    page.evaluate("window.hfsm.seek(0.05)")
    page.click('.agent[data-agent="a"] .drawing[data-machine="ping_pong"] button.enlarge')
    assert page.locator("#viewer").is_visible()
    assert page.inner_text("#viewer-title") == "a: ping_pong"
    assert page.eval_on_selector_all(
        "#viewer-figure g.node.active title", "ns => ns.map(n => n.textContent)"
    ) == ["receive"]
    fitted = int(page.inner_text("#viewer-scale").split()[0])
    box = page.locator("#viewer-stage").bounding_box()
    page.mouse.move(box["x"] + 100, box["y"] + 100)
    page.mouse.wheel(0, -400)
    page.wait_for_function(f"parseInt(document.getElementById('viewer-scale').textContent) > {fitted}")
    before = page.evaluate("document.getElementById('viewer-figure').style.transform")
    page.mouse.down()
    page.mouse.move(box["x"] + 160, box["y"] + 130)
    page.mouse.up()
    after = page.evaluate("document.getElementById('viewer-figure').style.transform")
    assert before != after and "scale" in after
    page.keyboard.press("0")
    assert int(page.inner_text("#viewer-scale").split()[0]) == fitted
    page.keyboard.press("Escape")
    assert not page.locator("#viewer").is_visible()
