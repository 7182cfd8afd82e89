"""The operator bar shows only on a live run that goes on: not on a replayed trace (even opened with
a token in its address), and it goes away when the live run ends. The server says which."""

from __future__ import annotations

import json
import urllib.request
from typing import Any

from hfsm.monitor.control import Control
from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server

RECORDS = [
    {"t": 0.0, "agent": "robot", "path": ["m"], "kind": "enter"},
    {"t": 0.0, "agent": "robot", "path": ["m", "a"], "kind": "enter", "do": "wait"},
]


def _meta(server: Server) -> Any:
    base = server.url.split("?")[0]
    with urllib.request.urlopen(base + "api/meta", timeout=10) as answer:
        return json.loads(answer.read())


def _status(page: Any, text: str) -> None:
    page.wait_for_function(f"document.getElementById('status').textContent.includes({json.dumps(text)})")


def test_a_replay_has_no_operator_bar_even_with_a_token(page: Any) -> None:
    server = Server(Hub(RECORDS), {}, "trace.jsonl")
    server.start()
    try:
        assert _meta(server)["control"] is None and _meta(server)["live"] is False
        page.goto(server.url + "?token=anything")
        _status(page, "replay")
        page.wait_for_timeout(300)  # the page has had its chance to set the bar up
        assert page.locator("#operator").is_hidden()
    finally:
        server.stop()


def test_a_live_run_has_the_bar_until_it_ends(page: Any) -> None:
    hub = Hub(live=True)
    for record in RECORDS:
        hub.offer(record)
    server = Server(hub, {}, "m", control=Control(["robot"], []))
    server.start()
    try:
        assert _meta(server)["control"] == {"agents": ["robot"], "breaks": []}
        page.goto(server.url)
        page.wait_for_function("!document.getElementById('operator').hidden")
        assert page.locator("#op-pause").is_visible()
        hub.offer(None)  # the run ends
        _status(page, "live run: ended")
        page.wait_for_function("document.getElementById('operator').hidden")
        assert _meta(server)["control"] is None
        page.reload()  # a page opened after the end has no bar either
        _status(page, "live run: ended")
        page.wait_for_timeout(300)
        assert page.locator("#operator").is_hidden()
    finally:
        server.stop()
