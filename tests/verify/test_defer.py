"""Failures put off while the failing agent's turn changes nothing (docs/VERIFY.md, *Failures that
change nothing*): the same verdicts as trying a failure at every tick, in no more states."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml
from verify_run import DATA, MACHINES, verify

from hfsm.verify import step

CORPUS: dict[str, list[dict[str, Any]]] = yaml.safe_load((DATA / "corpus.yaml").read_text())
FAILING = [
    [c["machine"], *c["args"], *c.get("trigger", [])]
    for c in CORPUS["buggy"] + CORPUS["correct"]
    if "--fail" in c["args"] + c.get("trigger", [])
]
PAPER = [
    ["elect_leader", "--agents", "r1,r2", "--param", "distance=1", "--param", "limit=5", "--loss", "1",
     "--fail", "1"],
    ["synchronised_lift_table", "--agents", "r1,r2", "--agent-param", "r1:role=leader", "--agent-param",
     "r2:role=assistant", "--param", "patience=5", "--fail", "1", "--delay", "1"],
]  # fmt: skip


def _file(name: str) -> Path:
    return DATA / f"{name}.yaml" if (DATA / f"{name}.yaml").exists() else MACHINES / f"{name}.yaml"


def _both(capsys: pytest.CaptureFixture[str], tmp_path: Path, case: list[str]) -> list[dict[str, Any]]:
    args = [str(DATA / a) if a.endswith(".yaml") else a for a in case[1:]]
    found = []
    for defer in (False, True):
        step.DEFER_FAILURES = defer
        try:
            code, verdict = verify(capsys, _file(case[0]), *args, out=tmp_path / f"{defer}.jsonl")
        finally:
            step.DEFER_FAILURES = True
        assert code in (0, 1), verdict["stderr"]
        found.append(verdict)
    return found


@pytest.mark.parametrize("case", FAILING + PAPER, ids=["-".join(c[:1] + c[-2:]) for c in FAILING + PAPER])
def test_putting_failures_off_finds_the_same_verdict(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, case: list[str]
) -> None:
    every, deferred = _both(capsys, tmp_path, case)
    assert (deferred["verdict"], deferred["kind"], deferred["exhausted"]) == (
        every["verdict"], every["kind"], every["exhausted"]
    )
    if every["verdict"] == "ok":
        assert deferred["states"] <= every["states"]


def test_a_failure_is_put_off_where_its_agent_waits(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    every, deferred = _both(capsys, tmp_path, ["barrier_timer", "--agents", "a,b,c", "--fail", "1"])
    assert deferred["states"] < every["states"]


def test_a_failure_put_off_is_tried_where_another_agent_ends(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """b's only failure that matters is in the tick a ends in, where b has nothing to do."""
    every, deferred = _both(capsys, tmp_path, ["ready_go", "--agents", "a,b", "--props", "one_leader.yaml",
                                                "--fail", "1"])  # fmt: skip
    assert deferred["kind"] == every["kind"] == "property"
