"""The JSONL trace writes json.dumps's bytes, in whole lines, by the end of every tick it is closed at."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm.trace import JsonlTrace, read_jsonl

SCALARS = st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False) | st.text()
VALUES = st.recursive(SCALARS, lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(), inner, max_size=3))
RECORDS = st.fixed_dictionaries(
    {"t": st.floats(0, 1e6), "agent": st.text(), "path": st.lists(st.text(), max_size=4), "kind": st.text()},
    optional={"event": st.text(), "data": VALUES, "outputs": st.dictionaries(st.text(), VALUES, max_size=3)},
)


def expected(records: list[dict[str, Any]]) -> str:
    return "".join(json.dumps(r, ensure_ascii=False, allow_nan=False, default=str) + "\n" for r in records)


@given(st.lists(st.lists(RECORDS, max_size=4), max_size=4))
def test_the_bytes_are_json_dumps_lines(tmp_path_factory: pytest.TempPathFactory, ticks: list[list[dict[str, Any]]]) -> None:
    path = tmp_path_factory.mktemp("trace") / "t.jsonl"
    trace = JsonlTrace(path)
    for records in ticks:
        for record in records:
            trace.write(record)
        trace.flush()
    trace.close()
    assert path.read_text(encoding="utf-8") == expected([r for records in ticks for r in records])


def test_lines_reach_the_file_whole_and_at_the_latest_when_due(tmp_path: Path) -> None:
    path = tmp_path / "t.jsonl"
    trace = JsonlTrace(path)
    trace.SAVE_SECONDS = 0.0  # due at once: the clock is read, and the lines saved, every tick
    trace.write({"t": 0.0, "agent": "a", "path": ["m"], "kind": "enter", "when": Path("x")})
    trace.flush()
    assert read_jsonl(path)[0]["when"] == "x"
    for tick in range(1, 100):
        trace.write({"t": tick * 0.05, "agent": "a", "path": ["m"], "kind": "exit", "outcome": f"{tick}"})
        trace.flush()
        assert read_jsonl(path)[-1]["outcome"] == f"{tick}"
    trace.close()


def test_after_quick_ticks_the_lines_are_saved_within_a_few_ticks_when_due(tmp_path: Path) -> None:
    path = tmp_path / "t.jsonl"
    trace = JsonlTrace(path)
    for _ in range(1000):  # quick ticks: the clock is read every few of them, LOOK_MOST at most
        trace.write_line("{}\n")
        trace.flush()
    trace.SAVE_SECONDS = 0.0
    for _ in range(trace.LOOK_MOST):
        trace.flush()
    assert path.read_text(encoding="utf-8") == "{}\n" * 1000
    trace.close()


def test_a_value_json_refuses_is_refused(tmp_path: Path) -> None:
    trace = JsonlTrace(tmp_path / "t.jsonl")
    with pytest.raises(ValueError):
        trace.write({"t": 0.0, "x": math.nan})
    trace.close()
