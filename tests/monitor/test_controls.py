"""The operator's controls on the page of a live run, in headless Chromium: pause, step, resume, a
held arc answered, a forced outcome, a message sent, a breakpoint; every action an `operator`
record, and the run replays byte for byte from its own trace. Requests without the run's token or
from another origin are refused."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.run import main as run_main

MACHINE = Path(__file__).resolve().parent / "data" / "operated.yaml"


@dataclass
class Live:
    url: str
    trace: Path
    process: subprocess.Popen[str]

    def records(self) -> list[dict[str, Any]]:
        return [json.loads(line) for line in self.trace.read_text().splitlines()]

    def ended(self) -> tuple[int, str]:
        out, _ = self.process.communicate(timeout=30)
        return self.process.returncode, out


@pytest.fixture
def live(tmp_path: Path) -> Iterator[Live]:
    trace = tmp_path / "live.jsonl"
    process = subprocess.Popen(
        [sys.executable, "-m", "hfsm.cli.run", str(MACHINE), "--autonomy", "low", "--realtime", "1",
         "--monitor", "--monitor-hold", "0", "--quiet", "--json", "--trace", str(trace)],
        stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True)  # fmt: skip
    assert process.stderr is not None
    line = ""
    while "monitor at" not in line:
        line = process.stderr.readline()
        assert line, "hfsm-run ended without serving the monitor"
    yield Live(line.split("monitor at ", 1)[1].strip(), trace, process)
    if process.poll() is None:
        process.kill()
        process.wait()


def _open(page: Any, url: str) -> None:
    page.goto(url)
    page.wait_for_function("!document.getElementById('operator').hidden")


def _said(page: Any, text: str) -> None:
    page.wait_for_function(f"document.getElementById('op-said').textContent.includes({json.dumps(text)})")


def test_a_held_arc_answered_a_message_sent_and_the_run_replays(
    page: Any, live: Live, tmp_path: Path
) -> None:
    _open(page, live.url)
    page.wait_for_function("document.getElementById('op-held').textContent.includes(\"holds 'done'\")")
    page.fill("#op-event", "done")
    page.click("#op-accept")
    _said(page, "sent: accept")
    page.wait_for_function(
        "window.hfsm.replay.records.some(r => r.kind === 'enter' && r.path[1] === 'listen')"
    )
    page.fill("#op-event", "")
    page.fill("#op-message", "go")
    page.fill("#op-data", '{"who": "<script>alert(1)</script>"}')
    page.click("#op-send")
    _said(page, "sent: message")
    code, out = live.ended()
    assert code == 0 and json.loads(out)["outcome"] == "done"
    ops = [(r["do"], r.get("event"), r.get("message")) for r in live.records() if r["kind"] == "operator"]
    assert ops == [("accept", "done", None), ("message", None, "go")]
    again = tmp_path / "again.jsonl"
    assert run_main([str(MACHINE), "--autonomy", "low", "--operator", str(live.trace), "--quiet",
                     "--trace", str(again)]) == 0  # fmt: skip
    assert again.read_bytes() == live.trace.read_bytes()


def test_pause_step_resume_and_a_forced_event(page: Any, live: Live) -> None:
    _open(page, live.url)
    page.click("#op-pause")
    _said(page, "sent: pause")
    page.wait_for_function("window.hfsm.replay.records.some(r => r.kind === 'operator' && r.do === 'pause')")
    paused = page.evaluate("window.hfsm.replay.records.find(r => r.kind === 'operator').t")
    page.click("#op-step")
    _said(page, "sent: step")
    page.wait_for_function("window.hfsm.replay.records.filter(r => r.kind === 'operator').length >= 2")
    page.click("#op-resume")
    _said(page, "sent: resume")
    page.wait_for_function("document.getElementById('op-held').textContent.includes(\"holds 'done'\")")
    page.fill("#op-event", "stop")
    page.click("#op-force")
    _said(page, "sent: force")
    code, out = live.ended()
    assert code == 0 and json.loads(out)["outcome"] == "stopped"
    ops = [(r["t"], r["do"]) for r in live.records() if r["kind"] == "operator"]
    assert [do for _, do in ops] == ["pause", "step", "resume", "force"]
    assert ops[1][0] == paused and ops[2][0] == round(
        paused + 0.05, 9
    )  # the clock stood still, then one tick


def test_a_breakpoint_set_on_the_page_pauses_the_run_after_its_record(page: Any, live: Live) -> None:
    _open(page, live.url)
    page.fill("#op-break", "enter:listen")
    page.click("#op-add-break")
    page.wait_for_function("document.getElementById('op-breaks').textContent.includes('enter:listen')")
    page.wait_for_function("document.getElementById('op-held').textContent.includes(\"holds 'done'\")")
    page.click("#op-accept")
    page.wait_for_function("window.hfsm.replay.records.some(r => r.kind === 'operator' && r.break)")
    page.click("#op-resume")
    page.fill("#op-message", "go")
    page.click("#op-send")
    code, _ = live.ended()
    assert code == 0
    hit = next(r for r in live.records() if r.get("break"))
    entered = next(r for r in live.records() if r["kind"] == "enter" and r["path"][-1] == "listen")
    assert hit["do"] == "pause" and hit["break"] == "enter:listen"
    assert hit["t"] == round(entered["t"] + 0.05, 9)  # at the start of the next tick


def test_requests_without_the_token_or_from_another_origin_are_refused(page: Any, live: Live) -> None:
    base, token = live.url.split("?token=")
    _open(page, f"{base}?token=wrong")  # the panel shows; its requests are refused
    page.click("#op-pause")
    _said(page, "refused: a control request needs this run's token")
    status = page.request.post(
        f"{base}api/control",
        data='{"do": "pause"}',
        headers={"X-HFSM-Token": token, "Origin": "http://evil.example"},
    ).status
    assert status == 403
    other = page.context.new_page()
    other.goto("about:blank")
    sent = other.evaluate(
        """([url, token]) => fetch(url, {method: "POST", headers: {"X-HFSM-Token": token}, body: '{"do": "pause"}'})
               .then(r => r.status, () => "blocked")""",
        [f"{base}api/control", token],
    )
    assert sent in ("blocked", 403)
    _open(page, live.url)
    page.click("#op-accept")  # the run's own page may: the hold is answered (or not yet there: ignored)
    page.wait_for_function("document.getElementById('op-held').textContent.includes(\"holds 'done'\")")
    page.click("#op-accept")
    page.fill("#op-message", "go")
    page.click("#op-send")
    assert live.ended()[0] == 0
    assert not any(r.get("do") == "pause" for r in live.records())
