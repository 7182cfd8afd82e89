"""tools/longrun.py: the trace read back whole or not, and a long run stopped from outside by a
signal, as a user stops one, leaves a whole trace."""

from __future__ import annotations

import json
import signal
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.longrun import (  # noqa: E402
    LOOP,
    Sample,
    _hfsm_run,
    _rates,
    _simulated,
    check_trace,
    growth,
    measure,
    slope,
)


def test_a_whole_trace_is_whole(tmp_path: Path) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text('{"t": 0}\n{"t": 0.05, "kind": "enter"}\n')
    assert check_trace(trace) == (2, True, "")


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("", "empty"),
        ('{"t": 0}\n{"t": 0.05, "ki', "the last line is not complete"),
        ('{"t": 0}\n[1, 2]\n', "line 2 is not a JSON object"),
        ('{"t": 0}\n{"t": \n', "line 2: "),
    ],
)
def test_a_cut_or_broken_trace_is_not_whole(tmp_path: Path, text: str, problem: str) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text(text)
    _, whole, found = check_trace(trace)
    assert not whole and found.startswith(problem)


def test_progress_lines_are_read_as_simulated_seconds() -> None:
    assert _simulated("simulated 01:30.0  tables at a wall 0/6") == 90.0
    assert _simulated("simulated 00:05.5") == 5.5
    assert _simulated("r1: did not end") is None
    assert _simulated("simulated soon") is None


def test_growth_is_from_the_second_sample_to_the_last() -> None:
    samples = [Sample(60.0 * i, 10.0 * i, mb) for i, mb in enumerate([100.0, 140.0, 141.5, 140.5])]
    assert growth(samples) == 0.5


def test_the_slope_is_a_least_squares_fit_from_the_second_sample_per_simulated_minute() -> None:
    flat = [Sample(60.0 * i, 10.0 * i, mb) for i, mb in enumerate([100.0, 140.0, 141.0, 140.0, 141.0])]
    assert slope(flat) == pytest.approx(0.2)
    rising = [Sample(30.0 * i, 10.0 * i, 100.0 + 7.5 * i) for i in range(6)]  # 15 MB a minute
    assert slope(rising) == pytest.approx(15.0)
    assert slope(rising[:2]) is None


@pytest.mark.slow
@pytest.mark.parametrize(("signum", "code"), [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_a_long_run_stopped_by_a_signal_leaves_a_whole_trace(tmp_path: Path, signum: int, code: int) -> None:
    trace = tmp_path / "t.jsonl"
    command = [_hfsm_run(), LOOP, "--scenario", "alloc_3_tasks", "--no-video", "--quiet",
               "--progress", "1", "--trace", str(trace)]
    run = measure("loop", command, trace, stop_at=2.0, stop_signal=signum)
    assert run.exit_code == code
    assert f"stopped by {signal.Signals(signum).name}" in run.summary
    assert [s.simulated for s in run.samples][:2] == [1.0, 2.0]
    assert all(s.rss_mb > 0 and s.cpu > 0 for s in run.samples)
    assert run.trace_whole and run.trace_problem == ""
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    assert len(records) == run.trace_lines and records[-1]["t"] >= 2.0
    # every state entered was left: the run ended its machines before the trace was closed
    assert sum(r["kind"] == "enter" for r in records) == sum(r["kind"] == "exit" for r in records)


def test_the_rates_project_the_full_length() -> None:
    samples = [Sample(60.0, 600.0, 150.0, 120.0), Sample(120.0, 1200.0, 150.0, 240.0)]
    (line,) = _rates(samples, 2100.0)
    assert "0.100 simulated s per wall s, 0.500 per CPU s" in line
    assert "the full 35 min at these rates: 5.8 h of wall time, 1.2 h of CPU" in line
    assert _rates(samples, 60.0) == [line.split(";")[0]]  # done: nothing to project
