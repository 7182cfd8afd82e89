"""Hostile text on the monitor's page, in headless Chromium: names, docs, message data and figures
holding script tags, event handlers, `javascript:` links, odd Unicode (RTL override, zero-width, a
lone surrogate) and 10 MB strings run nothing, show as text, and do not stall the page; a live feed
of 100,000 records a second is followed without the page hanging."""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.monitor import drawings, read_trace
from hfsm.monitor.hub import Hub
from hfsm.monitor.serve import Server

PWN = "<img src=x onerror=\"window.pwned=1;alert(1)\">"
SCRIPT = "<script>window.pwned=2;alert(2)</script>"
ODD = "\u202eevil\u200b\u2066x"
BIG = "B" * 10_000_000

SVG = """<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="200pt" height="80pt"
 viewBox="0 0 200 80" onload="window.pwned=3">
<script>window.pwned=4;alert(4)</script>
<style>* { background: url(http://example.invalid/x) }</style>
<g id="node1" class="node" onclick="window.pwned=5"><title>go</title>
<a xlink:href="javascript:window.pwned=6" href="javascript:window.pwned=6"><ellipse cx="50" cy="40" rx="40" ry="20"
 fill="url(http://example.invalid/y)"/></a>
<text x="20" y="44">go &lt;script&gt;window.pwned=7&lt;/script&gt;</text></g>
<foreignObject width="100" height="50"><iframe xmlns="http://www.w3.org/1999/xhtml" src="javascript:window.pwned=8"></iframe></foreignObject>
<image href="x" onerror="window.pwned=9"/>
<set attributeName="onmouseover" to="window.pwned=10"/>
</svg>"""

HOSTILE_MACHINE = f"""\
doc: '{SCRIPT} {PWN} javascript:alert(3) {ODD}'
outcomes: [done]
states:
  go:
    doc: '{PWN}'
    do: wait
    with: {{seconds: 1}}
    on: {{done: done}}
"""


def _records() -> list[dict[str, Any]]:
    agent = f"r{PWN}"
    return [
        {"t": 0.0, "agent": agent, "path": ["m"], "kind": "enter"},
        {"t": 0.0, "agent": agent, "path": ["m", "go"], "kind": "enter", "do": "wait"},
        {"t": 0.0, "agent": agent, "path": ["m", "go"], "kind": "event", "event": SCRIPT, "vars": {"x": BIG}},
        {"t": 0.0, "agent": ODD, "path": ["m"], "kind": "enter"},
        {"t": 0.0, "agent": ODD, "path": ["m", SCRIPT], "kind": "enter", "do": "javascript:alert(5)"},
        {"t": 0.1, "agent": agent, "path": ["m", "go"], "kind": "send", "to": ODD, "message": PWN,
         "data": {"html": SCRIPT, "odd": "\ud800"}},
        {"t": 0.15, "agent": ODD, "path": ["m", SCRIPT], "kind": "receive", "sender": agent, "message": PWN,
         "data": {"big": BIG}},
        {"t": 0.2, "agent": ODD, "path": ["m", BIG], "kind": "enter", "do": "wait"},
        {"t": 0.3, "agent": agent, "path": ["m"], "kind": "failed", "reason": f"{SCRIPT} \ud800"},
    ]


@pytest.fixture
def watched(page: Any) -> Iterator[dict[str, list[str]]]:
    """What the page must never do: open a dialog, log an error (a failed injected image, a refused
    script)."""
    seen: dict[str, list[str]] = {"dialogs": [], "errors": []}
    page.on("dialog", lambda d: (seen["dialogs"].append(d.message), d.dismiss()))
    page.on("console", lambda m: seen["errors"].append(m.text) if m.type == "error" else None)
    page.on("requestfailed", lambda r: seen["errors"].append(f"request {r.url}"))
    yield seen


def _served(records: list[dict[str, Any]], svgs: dict[str, str], title: str) -> Server:
    server = Server(Hub(records), svgs, title)
    server.start()
    return server


def _clean(page: Any, seen: dict[str, list[str]]) -> None:
    page.wait_for_timeout(500)  # an injected handler (image error, load) would have run by now
    assert seen == {"dialogs": [], "errors": []}
    assert page.evaluate("window.pwned") is None
    found = "#agents script, #agents foreignObject, #agents iframe, #agents image, #agents set, #agents style"
    assert page.locator(found).count() == 0
    assert page.evaluate(
        "[...document.querySelectorAll('*')].some(n => [...n.attributes].some(a => /^on/i.test(a.name) "
        "|| /javascript:/i.test(a.value) || /url\\(/i.test(a.value)))"
    ) is False


def test_a_hostile_trace_and_figure_run_nothing_and_show_as_text(
    page: Any, watched: dict[str, list[str]], tmp_path: Path
) -> None:
    trace = tmp_path / "hostile.jsonl"
    trace.write_text("".join(json.dumps(r) + "\n" for r in _records()))  # the surrogate as its JSON escape
    server = _served(read_trace(trace), {"m": SVG}, f"{SCRIPT}.jsonl")
    try:
        page.goto(server.url)
        page.wait_for_function("window.hfsm && window.hfsm.replay.records.length === 9", timeout=60000)
        page.evaluate("window.hfsm.seek(0.25)")
        text = page.inner_text("body")
        assert PWN in text and SCRIPT in text and "javascript:alert(5)" in text
        assert "\u202eevil" in text
        assert "… (10000007 characters)" in text  # the 10 MB state name (with its callee), cut
        assert "… (10000002 characters)" in text  # the 10 MB var, as JSON, cut
        assert len(text) < 200_000
        assert page.locator(".agent .drawing svg g.node title").first.text_content() == "go"
        assert "go <script>window.pwned=7</script>" in page.inner_text(".agent .drawing")
        page.click(".agent .drawing g.node")  # a click on the figure selects the state, runs nothing
        page.evaluate("window.hfsm.seek(0.3)")
        assert SCRIPT in page.inner_text(".agent .result")
        _clean(page, watched)
    finally:
        server.stop()


def test_a_hostile_machine_doc_shows_as_text_in_its_figure(
    page: Any, watched: dict[str, list[str]], tmp_path: Path
) -> None:
    machine = tmp_path / "m.yaml"
    machine.write_text(HOSTILE_MACHINE)
    records = [{"t": 0.0, "agent": "robot", "path": ["m"], "kind": "enter"},
               {"t": 0.0, "agent": "robot", "path": ["m", "go"], "kind": "enter", "do": "wait"}]
    server = _served(records, drawings(machine, []), "m.jsonl")
    try:
        page.goto(server.url)
        page.wait_for_selector(".agent .drawing svg")
        figure = page.inner_text(".agent .drawing")
        assert "<script>" in figure and "onerror" in figure  # Graphviz wraps long docs: parts of it
        _clean(page, watched)
    finally:
        server.stop()


def _feed(hub: Hub, rate: int, seconds: float, agents: int = 16) -> int:
    """`rate` records a second for `seconds`, in batches of a tenth of a second; how many."""
    names = [f"r{i}" for i in range(agents)]
    sent = 0
    begin = time.monotonic()
    for tick in range(int(seconds * 10)):
        t = round(tick * 0.1, 9)
        for i in range(rate // 10):
            name = names[i % agents]
            kind = ("enter", "exit", "send", "receive")[i % 4]
            record: dict[str, Any] = {"t": t, "agent": name, "path": ["m", f"s{i % 7}"], "kind": kind}
            if kind == "send":
                record.update(to="others", message="hello")
            elif kind == "receive":
                record.update(sender=names[(i + 1) % agents], message="hello")
            hub.offer(record)
            sent += 1
        delay = begin + (tick + 1) / 10 - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    hub.offer(None)
    return sent


@pytest.mark.slow
def test_a_feed_of_100000_records_a_second_never_hangs_the_page(page: Any) -> None:
    hub = Hub(live=True)
    hub.offer({"t": 0.0, "agent": "r0", "path": ["m"], "kind": "enter"})
    server = Server(hub, {}, "flood")
    server.start()
    try:
        page.goto(server.url)
        page.wait_for_function("window.hfsm && window.hfsm.replay.records.length > 0")
        result: dict[str, int] = {}
        feeder = threading.Thread(target=lambda: result.update(sent=_feed(hub, 100_000, 3.0)))
        feeder.start()
        answers = 0
        while feeder.is_alive():  # the page answers while it is flooded (a hang fails by Playwright's timeout)
            page.evaluate("window.hfsm.replay.records.length")
            answers += 1
            page.wait_for_timeout(200)
        feeder.join()
        page.wait_for_function(
            "document.getElementById('status').textContent.includes('live run: ended')", timeout=120000
        )
        shown = page.evaluate("window.hfsm.replay.records.length")
        assert answers > 0
        assert shown + hub.dropped == result["sent"] + 1  # every record is on the page, or counted as dropped
        page.evaluate("window.hfsm.seek(1.5)")  # and the page still draws a time of it
        assert page.locator(".agent").count() == 16
    finally:
        server.stop()
