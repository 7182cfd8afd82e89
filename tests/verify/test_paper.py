"""The examples and the paper's small machines, verified: no hang and no error under one lost
message or notice (and one failure where a timer covers a partner that fails)."""

from __future__ import annotations

from pathlib import Path

import pytest
from verify_run import EXAMPLES, MACHINES, verify

TEAMS = {"fail", "meet", "ping_pong"}  # examples run by two agents
PAIR = ("--agents", "r1,r2")
ROLES = ("--agent-param", "r1:role=leader", "--agent-param", "r2:role=assistant")

PAPER = [
    ("elect_leader", [*PAIR, "--param", "distance=1", "--loss", "1"]),
    ("elect_leader", [*PAIR, "--param", "distance=1", "--param", "limit=5", "--loss", "1", "--fail", "1"]),
    ("say", ["--param", "message=hi", "--param", "times=3", "--loss", "1"]),
    ("hear", ["--param", "message=hi", "--param", "limit=5"]),
    ("call_off", [*PAIR, "--param", "cycle=1", "--loss", "1", "--fail", "1"]),
    ("synchronised_lift_table", [*PAIR, *ROLES, "--param", "patience=5", "--loss", "1"]),
    ("step_together", [*PAIR, "--param", "direction=left", "--param", "cycle=1", "--param", "steps=1",
                       "--param", "split=1", "--param", "limit=3", "--values", "HOLDING"]),
    ("tararc_exchange", [*PAIR, "--param", "message=s", "--param", "team=[r1,r2]", "--param", "limit=0.2",
                         "--loss", "1"]),
]  # fmt: skip


@pytest.mark.parametrize("file", sorted(EXAMPLES.glob("*.yaml")), ids=lambda f: f.stem)
def test_every_example_verifies_under_a_lost_message(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, file: Path
) -> None:
    agents = "a,b" if file.stem in TEAMS else "robot"
    code, verdict = verify(capsys, file, "--agents", agents, "--loss", "1", out=tmp_path / "ce.jsonl")
    assert (code, verdict["verdict"], verdict["exhausted"]) == (0, "ok", True), verdict["stderr"]


@pytest.mark.slow
@pytest.mark.parametrize(("name", "args"), PAPER, ids=[f"{p[0]}-{i}" for i, p in enumerate(PAPER)])
def test_the_papers_small_machines_verify(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, name: str, args: list[str]
) -> None:
    values = tmp_path / "values.yaml"
    values.write_text("inputs: {holding: true}\n")  # the table stays held: no drop to find
    args = [str(values) if a == "HOLDING" else a for a in args]
    code, verdict = verify(capsys, MACHINES / f"{name}.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, verdict["verdict"], verdict["exhausted"]) == (0, "ok", True), verdict["stderr"]


def test_a_stand_in_that_fails_is_a_failure_outcome_with_goal_success(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """The lift's stand-in may end in `failure`: with --goal success, a run where it does is shown."""
    file = MACHINES / "synchronised_lift_table.yaml"
    code, verdict = verify(
        capsys, file, *PAIR, *ROLES, "--param", "patience=5", "--goal", "success", out=tmp_path / "ce.jsonl"
    )
    assert (code, verdict["kind"]) == (1, "failure_outcome")
    assert "lift_table of r" in verdict["stderr"] and "ended 'failure'" in verdict["stderr"]


def test_a_stand_in_outputs_what_its_saving_var_holds_at_first(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """TARARC's exchange stood in (`--stand-in`; its own machine is verified below): its `talking` is
    saved into a list var, so the stand-in says [] (not 0, which `len(vars.talking)` would refuse)."""
    args = ["--agents", "r1,r2", "--param", "message=s", "--param", "barrier=close", "--param", "limit=10"]
    args += ["--stand-in", "tararc_exchange"]
    args += ["--agent-param", "r1:team=[r2]", "--agent-param", "r2:team=[r1]", "--loss", "1", "--fail", "1"]
    code, verdict = verify(capsys, MACHINES / "tararc_share.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, verdict["verdict"], verdict["exhausted"]) == (0, "ok", True), verdict["stderr"]
