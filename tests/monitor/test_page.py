"""The monitor's page in a real browser (headless Chromium): replay, scrub, step, fold, live."""

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


@pytest.fixture
def ping_pong(tmp_path: Path) -> Iterator[Server]:
    trace = tmp_path / "pp.jsonl"
    assert run_main([str(PING_PONG), "--agents", "a,b", "--trace", str(trace), "--quiet"]) == 0
    server = Server(Hub(read_trace(trace)), drawings(PING_PONG, []), "pp.jsonl")
    server.start()
    yield server
    server.stop()


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
    server = Server(Hub(read_trace(trace)), drawings(meet, []), trace.name)
    server.start()
    try:
        _open(page, server.url)
        page.evaluate("window.hfsm.seek(0.5)")
        assert "waiting at a barrier" in page.inner_text('.agent[data-agent="a"] details[data-key="meet/meet"]')
        page.evaluate("window.hfsm.seek(2)")
        assert "last barrier passed at 1.05 s (meet), with b" in page.inner_text('.agent[data-agent="a"] .mailbox')
    finally:
        server.stop()
