"""`hfsm-run` against bad flags, outputs that are inputs, full disks and stop signals."""

from __future__ import annotations

import json
import logging
import signal
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from hfsm.cli.run import main
from hfsm.cli.tracefile import TraceFile
from hfsm.runtime.core import FatalError
from hfsm.trace import read_jsonl

Machine = Callable[[str, str], Path]
ROOT = Path(__file__).resolve().parents[2]
HELLO = ROOT / "examples" / "hello.yaml"
LOOP = """
    outcomes: [done]
    vars: {n: 0}
    states:
      say: {do: log, with: {text: "n=${vars.n}"}, on: {done: count}}
      count: {do: set, with: {n: "${vars.n + 1}"}, on: {done: pause}}
      pause: {do: wait, with: {seconds: 1}, on: {done: say}}
"""


def run(capsys: pytest.CaptureFixture[str], *argv: object) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize(
    ("flag", "value"),
    [
        ("--max-time", "1e308"),
        ("--max-time", "nan"),
        ("--max-time", "-1"),
        ("--dt", "0"),
        ("--dt", "inf"),
        ("--dt", "1e-9"),
        ("--seed", "-1"),
        ("--seed", "1e3"),
        ("--seed", str(2**70)),
    ],
)
def test_numeric_flags_out_of_range_exit_2(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, flag: str, value: str
) -> None:
    trace = tmp_path / "t.jsonl"
    code, out, err = run(capsys, HELLO, "--trace", trace, flag, value)
    assert code == 2 and out == "" and f"argument {flag}" in err and "Traceback" not in err
    assert not trace.exists()


@pytest.mark.parametrize(
    ("flag", "value"),
    [
        ("--radio-latency", "nan"),
        ("--radio-latency", "-0.1"),
        ("--radio-latency", "1e308"),
        ("--radio-loss", "nan"),
        ("--radio-loss", "1.5"),
        ("--image-size", "20000x20000"),
        ("--image-size", "8x8"),
        ("--progress", "inf"),
    ],
)
def test_world_flags_out_of_range_exit_2_before_anything_is_written(
    machine: Machine, capsys: pytest.CaptureFixture[str], tmp_path: Path, flag: str, value: str
) -> None:
    out_dir = tmp_path / "out"
    code, _, err = run(capsys, ROOT / "machines" / "move_furniture.yaml", "--out", out_dir, flag, value)
    assert code == 2 and f"argument {flag}" in err and "Traceback" not in err
    assert not out_dir.exists()


def test_agents_that_do_not_match_the_scenario_write_nothing(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    out_dir = tmp_path / "out"
    code, _, err = run(capsys, ROOT / "machines" / "move_furniture.yaml", "--out", out_dir, "--agents", "r1")
    assert code == 2 and "this world's agents are r1,r2" in err
    assert list(out_dir.iterdir()) == [] and "wrote" not in err


def test_a_trace_onto_an_input_is_refused_and_the_input_kept(
    machine: Machine, capsys: pytest.CaptureFixture[str]
) -> None:
    callee = machine("callee", "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: 1}, on: {done: done}}\n")
    top = machine("top", "outcomes: [done]\nstates:\n  a: {do: callee, on: {done: done}}\n")
    before = callee.read_bytes()
    for target in (top, callee):
        code, _, err = run(capsys, top, "--trace", target)
        assert code == 2 and "would overwrite an input file" in err
    assert callee.read_bytes() == before


def test_a_trace_onto_a_full_disk_is_exit_1(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, HELLO, "--trace", "/dev/full")
    assert code == 1 and "error: --trace: cannot write /dev/full: No space left on device" in err
    assert "Traceback" not in err and "wrote /dev/full" not in err
    assert "ended in 'done'" in out


class _FillingFile:
    """A text file on a disk that fills after `room` characters."""

    def __init__(self, path: Path, room: int) -> None:
        self.real = path.open("w", encoding="utf-8")
        self.room = room

    def write(self, text: str) -> int:
        if len(text) > self.room:
            self.real.write(text[: self.room])
            self.room = 0
            raise OSError(28, "No space left on device")
        self.room -= len(text)
        return self.real.write(text)

    def flush(self) -> None:
        self.real.flush()

    def tell(self) -> int:
        return self.real.tell()

    def close(self) -> None:
        self.real.close()


def test_a_disk_that_fills_leaves_the_whole_lines_written_before(tmp_path: Path) -> None:
    path = tmp_path / "t.jsonl"
    trace = TraceFile(path)
    trace._file = _FillingFile(path, 100)  # type: ignore[assignment]
    trace.write({"t": 0, "kind": "enter", "path": ["a"]})
    trace.flush()
    trace.write({"t": 1, "kind": "enter", "path": ["a", "b" * 80]})
    with pytest.raises(FatalError, match="No space left"):
        trace.flush()
    trace.flush()  # reported once
    trace.close()
    assert read_jsonl(path) == [{"t": 0, "kind": "enter", "path": ["a"]}]


def test_non_finite_numbers_in_a_record_keep_the_line_json(tmp_path: Path) -> None:
    path = tmp_path / "t.jsonl"
    trace = TraceFile(path)
    trace.write({"t": 0, "vars": {"x": float("nan"), "y": [float("inf")]}})
    trace.close()
    assert read_jsonl(path) == [{"t": 0, "vars": {"x": "nan", "y": ["inf"]}}]


@pytest.fixture
def signal_on_log(request: pytest.FixtureRequest) -> Iterator[Callable[[int, int], None]]:
    """Raise a signal when the machine logs for the k-th time (deterministic, in process)."""
    logger = logging.getLogger("hfsm.log")
    level = logger.level
    logger.setLevel(logging.INFO)
    handlers: list[logging.Handler] = []

    def arm(signum: int, k: int, again: bool = False) -> None:
        seen = [0]

        class Raise(logging.Handler):
            def emit(self, record: logging.LogRecord) -> None:
                seen[0] += 1
                if seen[0] == k or (again and seen[0] == k + 1):
                    signal.raise_signal(signum)

        handler = Raise()
        logger.addHandler(handler)
        handlers.append(handler)

    yield arm
    logger.setLevel(level)
    for handler in handlers:
        logger.removeHandler(handler)


@pytest.mark.parametrize(("signum", "code"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_stop_signal_ends_the_run_cleanly(
    machine: Machine,
    capsys: pytest.CaptureFixture[str],
    tmp_path: Path,
    signal_on_log: Any,
    signum: int,
    code: int,
) -> None:
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    signal_on_log(signum, 3)
    trace = tmp_path / "t.jsonl"
    got, out, err = run(capsys, machine("loop", LOOP), "--trace", trace, "--agents", "a,b")
    assert got == code and "Traceback" not in err
    assert f"error: stopped by {signal.Signals(signum).name}" in err and "did not end" in out
    records = [json.loads(line) for line in trace.read_text().splitlines()]
    enters = sum(r["kind"] == "enter" for r in records)
    assert enters == sum(r["kind"] == "exit" for r in records) > 0
    assert records[-1] == {"t": records[-1]["t"], "agent": "b", "path": ["loop"], "kind": "exit", "outcome": None}
    assert {s: signal.getsignal(s) for s in before} == before  # as they were, even if inherited ignored


def test_a_second_ctrl_c_stops_at_once(
    machine: Machine, capsys: pytest.CaptureFixture[str], signal_on_log: Any
) -> None:
    signal_on_log(signal.SIGINT, 2, again=True)
    code, _, err = run(capsys, machine("loop", LOOP))
    assert code == 130 and "stopped by SIGINT" in err and "Traceback" not in err


def test_an_out_folder_that_is_a_file_is_exit_2(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    afile = tmp_path / "afile"
    afile.write_text("")
    code, _, err = run(capsys, ROOT / "machines" / "move_furniture.yaml", "--out", afile)
    assert code == 2 and "cannot write in" in err and "Traceback" not in err


def test_a_symlink_loop_as_file_is_exit_2(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    one, two = tmp_path / "one.yaml", tmp_path / "two.yaml"
    one.symlink_to(two)
    two.symlink_to(one)
    code, _, err = run(capsys, one, "--check")
    assert code == 2 and err.startswith(f"{one}:1:1: error[E105]") and "Traceback" not in err
