"""tools/bench_copy.py: a state's dump and load by two versions of hfsm/verify/snapshot.py."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import load_tool

ROOT = Path(__file__).resolve().parents[2]
bench_copy = load_tool("bench_copy")


def test_both_versions_copy_the_same_states(capsys: pytest.CaptureFixture[str]) -> None:
    file = ROOT / "tests" / "verify" / "data" / "quorum.yaml"
    other = ROOT / "hfsm" / "verify" / "snapshot.py"  # this code again, loaded as another module
    assert bench_copy.main([str(other), "--rounds", "2", str(file), "--agents", "a,b,c", "--loss", "1"]) == 0
    out = capsys.readouterr().out
    states = int(out.split(" states")[0])
    assert states > 10
    rows = {line.split(" | ")[0].strip("| "): line for line in out.splitlines() if line.startswith("| ")}
    assert set(rows) == {"code", "this", "other"}
    assert all(" / " in rows[name] for name in ("this", "other"))
