"""A breakpoint on a condition set on the page of a live run: refused at its column when it does not
compile, and, once set, pausing the run at the start of the tick after the one that made it true."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.run import main as run_main

COUNTER = Path(__file__).resolve().parent / "data" / "counter.yaml"


@pytest.fixture
def paused_run(tmp_path: Path) -> Iterator[tuple[str, Path, subprocess.Popen[str]]]:
    """A live run of the counter, paused by its operator script before its first tick."""
    (tmp_path / "ops.json").write_text(json.dumps([{"t": 0, "do": "pause"}]))
    trace = tmp_path / "live.jsonl"
    process = subprocess.Popen(
        [sys.executable, "-m", "hfsm.cli.run", str(COUNTER), "--world", "none", "--realtime", "1",
         "--operator", str(tmp_path / "ops.json"), "--monitor", "--monitor-hold", "0", "--quiet", "--json",
         "--trace", str(trace)],
        stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True)  # fmt: skip
    assert process.stderr is not None
    line = ""
    while "monitor at" not in line:
        line = process.stderr.readline()
        assert line, "hfsm-run ended without serving the monitor"
    yield line.split("monitor at ", 1)[1].strip(), trace, process
    if process.poll() is None:
        process.kill()
        process.wait()


def _said(page: Any, text: str) -> None:
    page.wait_for_function(f"document.getElementById('op-said').textContent.includes({json.dumps(text)})")


def test_a_condition_set_on_the_page_stops_the_run_at_the_right_tick(
    page: Any, paused_run: tuple[str, Path, subprocess.Popen[str]], tmp_path: Path
) -> None:
    url, trace, process = paused_run
    page.goto(url)
    page.wait_for_function("!document.getElementById('operator').hidden")
    page.fill("#op-break", "cond:vars.nn > 1")
    page.click("#op-add-break")
    _said(page, "refused: unknown variable 'nn'; did you mean 'n'? (column 6 of 'cond:vars.nn > 1')")
    page.fill("#op-break", "cond:vars.n == 3")
    page.click("#op-add-break")
    page.wait_for_function("document.getElementById('op-breaks').textContent.includes('cond:vars.n == 3')")
    page.click("#op-resume")
    page.wait_for_function("window.hfsm.replay.records.some(r => r.kind === 'operator' && r.break)")
    hit = page.evaluate("window.hfsm.replay.records.find(r => r.kind === 'operator' && r.break)")
    assert (hit["t"], hit["do"], hit["break"]) == (0.25, "pause", "cond:vars.n == 3")  # n became 3 at 0.2 s
    assert page.evaluate("window.hfsm.replay.end") == 0.25  # nothing of the tick after the pause ran
    page.click("#op-resume")
    out, _ = process.communicate(timeout=30)
    assert process.returncode == 0 and json.loads(out)["outputs"] == {"n": 5}
    again = tmp_path / "again.jsonl"
    assert run_main([str(COUNTER), "--world", "none", "--operator", str(trace), "--quiet", "--trace", str(again)]) == 0
    assert again.read_bytes() == trace.read_bytes()  # the live run replays from its own trace
