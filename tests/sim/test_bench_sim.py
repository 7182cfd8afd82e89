from __future__ import annotations

from helpers import load_tool


def test_scripted_run_reports_a_rate() -> None:
    rtf, images, by_cpu = load_tool("bench_sim").scripted_rtf(1.0, 2.0)
    assert rtf > 0 and by_cpu > 0 and images == 4
