"""tools/bench_graph.py: it times a folder and rewrites only its own section of PERFORMANCE.md."""

from __future__ import annotations

import importlib.util
from types import ModuleType

from .helpers_diagram import DATA, ROOT

TOOL = ROOT / "tools" / "bench_graph.py"


def _load() -> ModuleType:
    spec = importlib.util.spec_from_file_location("bench_graph", TOOL)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_drawing_a_folder_is_timed() -> None:
    assert 0 < _load().seconds_to_draw(DATA, "dot", repeats=1) < 10
