"""`--resume` in the simulator: the same scenario and seed, taken from the trace, give the same
trace up to T (robots, radio, poses), checked byte for byte as it is written."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hfsm.cli.run import main

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_a_simulator_run_resumes_with_its_prefix_checked(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    machine = str(ROOT / "machines" / "move_furniture.yaml")
    first = tmp_path / "first.jsonl"
    common = ["--no-video", "--out", str(tmp_path), "--quiet", "--json"]
    main([machine, "--seed", "1", "--max-time", "3", "--trace", str(first), *common])
    capsys.readouterr()
    again = tmp_path / "again.jsonl"
    main([machine, "--resume", f"{first}@1.5", "--max-time", "3", "--trace", str(again), *common])
    capsys.readouterr()
    old, new = first.read_text().splitlines(), again.read_text().splitlines()
    head = json.loads(old[0])
    assert head["kind"] == "run" and head["args"] == ["--seed", "1"]
    prefix = sum(1 for line in old if json.loads(line)["t"] <= 1.5)
    assert any('"pose"' in line for line in old[:prefix])  # the world's records are checked too
    assert new[:prefix] == old[:prefix]
    assert json.loads(new[prefix])["kind"] == "resume"
    assert len(new) > prefix + 1  # it went on after T
