from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

TOOL = Path(__file__).resolve().parents[2] / "tools" / "bench_sim.py"


def _load() -> ModuleType:
    spec = importlib.util.spec_from_file_location("bench_sim", TOOL)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_scripted_run_reports_a_rate() -> None:
    rtf, images = _load().scripted_rtf(1.0, 2.0)
    assert rtf > 0 and images == 4
