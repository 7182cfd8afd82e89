"""The monitor's page in a real browser (headless Chromium): replay, scrub, step, fold, live."""

from __future__ import annotations

import contextlib
import json
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


@contextlib.contextmanager
def _served(machine: Path, trace: Path) -> Iterator[Server]:
    """The monitor replaying `trace`, drawn from `machine`'s library, stopped afterwards."""
    server = Server(Hub(read_trace(trace)), drawings(machine, []), trace.name)
    server.start()
    try:
        yield server
    finally:
        server.stop()


@pytest.fixture
def ping_pong(tmp_path: Path) -> Iterator[Server]:
    trace = tmp_path / "pp.jsonl"
    assert run_main([str(PING_PONG), "--agents", "a,b", "--trace", str(trace), "--quiet"]) == 0
    with _served(PING_PONG, trace) as server:
        yield server


def _open(page: Any, url: str) -> None:
    page.goto(url)
    page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")


def _lit(page: Any, agent: str) -> list[str]:
    return page.eval_on_selector_all(
        f'.agent[data-agent="{agent}"] .drawing g.node.active title', "ns => ns.map(n => n.textContent)")


def test_replay_shows_the_active_states_messages_and_mailbox_at_a_chosen_time(page: Any, ping_pong: Server) -> None:
    _open(page, ping_pong.url)
    page.evaluate("window.hfsm.seek(0.05)")
    assert page.inner_text("#time") == "0.05 s"
    assert page.locator('.agent[data-agent="a"] summary[data-path="ping_pong/receive"]').count() == 1
    assert _lit(page, "a") == ["receive"] and _lit(page, "b") == ["receive"]
    assert "ball from a" in page.inner_text('.agent[data-agent="b"] .mailbox')
    assert page.locator("#sequence line.msg.received").count() == 1
    assert page.locator("#sequence line.msg.lost").count() == 0
    top = '.agent[data-agent="b"] details.block[data-key="ping_pong"]'
    assert "ping_pong's timer 29.95 s left" in page.inner_text(f"{top} > .facts")
    page.evaluate("window.hfsm.seek(0.1)")
    assert page.inner_text(f"{top} > table.vars") == 'hits\t1\nlast_sender\t"a"'


def test_scrub_and_step_move_through_time(page: Any, ping_pong: Server) -> None:
    _open(page, ping_pong.url)
    page.fill("#slider", "0")
    page.dispatch_event("#slider", "input")
    assert page.inner_text("#time") == "0.00 s"
    page.click("#step")
    assert page.inner_text("#time") == "0.05 s"
    page.click("#step")
    assert page.inner_text("#time") == "0.10 s"
    page.click("#back")
    assert page.inner_text("#time") == "0.05 s"
    page.evaluate("window.hfsm.seek(1e9)")
    assert page.inner_text('.agent[data-agent="b"] .result') == "ended in 'won'"
    assert page.inner_text('.agent[data-agent="a"] .result') == "ended in 'lost'"


def test_a_depth_folds_and_stays_folded(page: Any, ping_pong: Server) -> None:
    _open(page, ping_pong.url)
    page.evaluate("window.hfsm.seek(0.05)")
    top = page.locator('.agent[data-agent="a"] details.block[data-key="ping_pong"]')
    assert top.locator(":scope > .drawing").is_visible()
    top.locator(":scope > summary").click()
    assert not top.locator(":scope > .drawing").is_visible()
    page.click("#step")
    assert not top.locator(":scope > .drawing").is_visible()


def test_a_live_run_updates_the_page_while_it_goes(page: Any, tmp_path: Path) -> None:
    machine = ROOT / "examples" / "blink.yaml"
    run = subprocess.Popen(
        [sys.executable, "-m", "hfsm.cli.run", str(machine), "--param", "limit=3", "--realtime", "1",
         "--monitor", "--monitor-hold", "0", "--quiet", "--trace", str(tmp_path / "b.jsonl")],
        stderr=subprocess.PIPE, text=True)
    try:
        assert run.stderr is not None
        line = ""
        while "monitor at" not in line:
            line = run.stderr.readline()
            assert line, "hfsm-run ended without serving the monitor"
        url = line.split("monitor at ", 1)[1].strip()
        _open(page, url)
        assert "live run" in page.inner_text("#status")
        page.wait_for_function("parseFloat(document.getElementById('time').textContent) >= 1.0")
        first = float(page.inner_text("#time").split()[0])
        page.wait_for_function(f"parseFloat(document.getElementById('time').textContent) > {first}")
        assert page.locator('.agent[data-agent="robot"] summary[data-path^="blink/"]').count() == 1
        page.wait_for_function("document.getElementById('status').textContent.includes('ended')")
        assert page.locator('.agent[data-agent="robot"].ended .drawing[data-machine="blink"]').is_visible()
    finally:
        assert run.wait(timeout=30) == 0


def test_the_monitor_never_changes_the_trace(tmp_path: Path) -> None:
    plain, watched = tmp_path / "plain.jsonl", tmp_path / "watched.jsonl"
    args = [str(PING_PONG), "--agents", "a,b", "--quiet", "--trace"]
    assert run_main([*args, str(plain)]) == 0
    assert run_main([*args, str(watched), "--monitor", "--monitor-hold", "0"]) == 0
    assert plain.read_bytes() == watched.read_bytes()


def test_a_barrier_shows_while_waiting_and_who_it_heard_once_passed(page: Any, tmp_path: Path) -> None:
    meet = tmp_path / "meet.yaml"
    meet.write_text(
        "outcomes: [together, alone]\nstates:\n  walk:\n    do: wait\n"
        "    with: {seconds: \"${0.2 if agent.id == 'a' else 1.0}\"}\n    on: {done: meet}\n"
        "  meet:\n    do: barrier\n    with: {name: meet}\n    timer: 10\n    on: {passed: together, timeout: alone}\n")
    trace = tmp_path / "meet.jsonl"
    assert run_main([str(meet), "--agents", "a,b", "--trace", str(trace), "--quiet"]) == 0
    with _served(meet, trace) as server:
        _open(page, server.url)
        page.evaluate("window.hfsm.seek(0.5)")
        assert "waiting at a barrier" in page.inner_text('.agent[data-agent="a"] details[data-key="meet/meet"]')
        page.evaluate("window.hfsm.seek(2)")
        assert "last barrier passed at 1.05 s (meet), with b" in page.inner_text('.agent[data-agent="a"] .mailbox')


def _room_trace(path: Path) -> None:
    """A room run's records as the simulator and clear_room write them: r1's belief (`drawn`: a
    claimed corridor, where it believes r2 stands) and what it sensed (a table, in its start frame)."""
    drawn = {"rects": [[1.0, 0.0, 0.0, 2.0, 1.0, "table1 corridor"]], "points": [[-1.0, 1.0, "r2"]]}
    sensed = {"start": [0.0, -1.0, 90.0], "tables_in_view": {
        "t": 0.5, "value": [{"x": 1.0, "y": 1.0, "heading": 0.0, "length": 0.8, "width": 0.5, "clipped": False}]}}
    records = [
        {"t": 0.0, "agent": "r1", "path": ["clear_room"], "kind": "enter"},
        {"t": 0.0, "agent": "r1", "path": ["clear_room", "assign"], "kind": "enter", "do": "room_assign"},
        {"t": 0.5, "agent": "r1", "path": ["clear_room", "assign"], "kind": "event", "event": "assigned",
         "vars": {"drawn": drawn}},
        {"t": 0.5, "agent": "world", "path": [], "kind": "pose", "room": [6.0, 4.0],
         "tables": [[-1.0, 0.0, 0.0, 0.8, 0.5, 0.0]], "robots": {"r1": [0.0, -1.0, 1.5708]}, "targets": [],
         "sensed": {"r1": sensed}},
    ]
    path.write_text("".join(json.dumps(r) + "\n" for r in records), encoding="utf-8")


def _pixel(page: Any, x: int, y: int) -> list[int]:
    return page.evaluate(f"Array.from(document.getElementById('room').getContext('2d').getImageData({x}, {y}, 1, 1).data)")


def test_the_room_view_draws_claimed_corridors_beliefs_and_what_each_robot_sensed(page: Any, tmp_path: Path) -> None:
    trace = tmp_path / "room.jsonl"
    _room_trace(trace)
    with _served(PING_PONG, trace) as server:
        _open(page, server.url)
        page.evaluate("window.hfsm.seek(1)")
        # 6 x 4 m on 320 px: 50 px a metre, the room's centre at (160, 160)
        floor, corridor = _pixel(page, 260, 60), _pixel(page, 210, 175)  # a corner; inside the corridor
        assert corridor[0] > floor[0] + 15 and corridor[1] > floor[1] + 15  # tinted yellow
        # r1 was told it started at (0, -1) facing +y: its table 1 m ahead and 1 m left is at (-1, 0),
        # turned 90 degrees: its outline's near edge runs along y = 0.4 m (pixel row 140), magenta
        edge = [_pixel(page, x, y) for x in (105, 110, 115) for y in (139, 140, 141)]
        assert any(p[0] > 180 and p[2] > 180 and p[1] < 160 for p in edge), edge
        assert page.eval_on_selector_all("#belief option", "os => os.map(o => o.value)") == ["", "r1"]
        believed = _pixel(page, 115, 110)  # where r1 believes r2 stands, (-1, 1): drawn for r1 alone
        page.select_option("#belief", "r1")
        circle = [_pixel(page, x, y) for x in range(113, 118) for y in (109, 110, 111)]
        assert any(p[2] > 150 and p[1] > 130 for p in circle), circle
        assert not (believed[2] > 150 and believed[1] > 130)


def test_a_status_kept_last_shows_once_in_the_mailbox_and_every_copy_as_received(page: Any, tmp_path: Path) -> None:
    talk = tmp_path / "talk.yaml"
    talk.write_text(
        "vars: {n: 0}\noutcomes: [done]\nstates:\n  who:\n    choose:\n      - {if: \"agent.id == 'a'\", then: say}\n"
        "      - {else: rest}\n  say:\n    do: send\n    with: {message: status, to: b, keep: last, data: {n: '${vars.n}'}}\n"
        "    on: {sent: count}\n  count:\n    do: set\n    with: {n: '${vars.n + 1}'}\n    on: {done: more}\n"
        "  more:\n    choose:\n      - {if: 'vars.n < 3', then: pause}\n      - {else: done}\n"
        "  pause:\n    do: wait\n    with: {seconds: 0.05}\n    on: {done: say}\n"
        "  rest:\n    do: wait\n    with: {seconds: 1}\n    on: {done: done}\n")
    trace = tmp_path / "talk.jsonl"
    assert run_main([str(talk), "--agents", "a,b", "--trace", str(trace), "--quiet"]) == 0
    with _served(talk, trace) as server:
        _open(page, server.url)
        page.evaluate("window.hfsm.seek(0.5)")
        assert page.inner_text('.agent[data-agent="b"] .mailbox') == "mailbox: status from a"
        fates = page.evaluate("window.hfsm.replay.fates().map(m => m.got.b)")
        assert fates == [0.05, 0.1, 0.15]
