"""tools/profile_verify.py: where the CPU time of a search goes, part by part."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import load_tool

ROOT = Path(__file__).resolve().parents[2]
profile_verify = load_tool("profile_verify")


def test_each_part_of_a_search_is_timed(capsys: pytest.CaptureFixture[str]) -> None:
    file = ROOT / "tests" / "verify" / "data" / "quorum.yaml"
    assert profile_verify.main([str(file), "--agents", "a,b,c", "--loss", "1", "--fail", "1"]) == 0
    out = capsys.readouterr().out
    assert "ok, 224 states" in out
    lines = [line for line in out.splitlines() if line.startswith("| ")]
    rows = {line.split(" | ")[0].strip("| "): line.split(" | ") for line in lines}
    assert int(rows["tick (next_state)"][1]) >= 224  # a tick a state reached, at least
    assert int(rows["dump (copy to bytes)"][1]) > 0 and int(rows["load (copy from bytes)"][1]) > 0
    shares = [int(row[3].rstrip(" %")) for name, row in rows.items() if name != "part"]
    assert 95 <= sum(shares) <= 105
