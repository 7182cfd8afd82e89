from __future__ import annotations

from pathlib import Path

import pytest

from hfsm.cli.monitor import main


def test_a_bad_trace_line_is_file_line_col_and_exit_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text('{"t": 0, "agent": "robot", "path": ["m"], "kind": "enter"}\n{"t": 0,\n')
    assert main([str(trace), "--for", "0"]) == 2
    assert f"{trace}:2:9: not a trace record" in capsys.readouterr().err


def test_a_record_without_a_path_and_a_missing_file_are_exit_2(tmp_path: Path,
                                                               capsys: pytest.CaptureFixture[str]) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text("[1, 2]\n")
    assert main([str(trace), "--for", "0"]) == 2
    assert f"{trace}:1:1: not a trace record" in capsys.readouterr().err
    assert main([str(tmp_path / "missing.jsonl")]) == 2
    assert main([str(trace), "--port", "70000"]) == 2


def test_a_good_trace_is_served_and_the_command_ends_when_asked(tmp_path: Path,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    trace = tmp_path / "t.jsonl"
    trace.write_text('{"t": 0, "agent": "robot", "path": ["nowhere"], "kind": "enter"}\n')
    assert main([str(trace), "--for", "0"]) == 0
    err = capsys.readouterr().err
    assert "no machine file 'nowhere' found" in err and "serving" in err and "http://127.0.0.1:" in err
