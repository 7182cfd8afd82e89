"""tools/bench_graph.py: it times a folder and rewrites only its own section of PERFORMANCE.md."""

from __future__ import annotations

from helpers import load_tool

from .helpers_diagram import DATA


def test_drawing_a_folder_is_timed() -> None:
    assert 0 < load_tool("bench_graph").seconds_to_draw(DATA, "dot", repeats=1) < 10
