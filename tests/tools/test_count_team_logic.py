"""tools/count_team_logic.py: what counts as a line of team logic."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))

from count_team_logic import count, python_lines, yaml_lines


def test_python_lines_leave_out_docstrings_comments_and_blank_lines() -> None:
    text = '"""Module.\n\nMore."""\n\n# a comment\ndef f(x: int) -> int:\n    """Doc."""\n    return (x +\n            1)  # c\n'
    assert python_lines(text) == 3


def test_yaml_lines_leave_out_docs_comments_and_blank_lines() -> None:
    text = ("# header\ndoc: >\n  folded\n  text\nparams:\n  a: {type: int}\nstates:\n  s:\n"
            "    doc: one line\n    do: wait\n\n    on: {done: x}\n    choose:\n      - doc: >\n"
            "          long\n        if: true\n")
    assert yaml_lines(text) == 8


def test_the_counts_add_up() -> None:
    counts = count()
    assert counts["python"] == sum(dict(counts["python_files"]).values())  # type: ignore[call-overload]
    assert 0 < int(counts["python_protocols"]) <= int(counts["python"])  # type: ignore[call-overload]
    assert int(counts["yaml"]) > 0  # type: ignore[call-overload]
