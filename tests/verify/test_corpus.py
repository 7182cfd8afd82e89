"""The corpus (tests/verify/data): each planted bug found with its kind, under the choice that shows
it and not without; each correct machine proved with the space exhausted; every counterexample
replayed byte for byte."""

from __future__ import annotations

from pathlib import Path

import pytest
from verify_run import DATA, replay, verify

AB = ("--agents", "a,b")

BUGGY = [
    ("ping_once", [*AB], ["--loss", "1"], "hang"),
    ("barrier_forever", [*AB], ["--fail", "1"], "hang"),
    ("elect_race", [*AB, "--props", str(DATA / "one_leader.yaml")], ["--loss", "1"], "property"),
    ("elect_work", [*AB, "--props", str(DATA / "one_worker.yaml")], ["--loss", "1"], "property"),
    ("early_go", [*AB], ["--delay", "1"], "error"),
    ("ask_once", [*AB, "--goal", "success"], ["--loss", "1"], "failure_outcome"),
    ("ask_once", [*AB, "--props", str(DATA / "asking_quick.yaml")], ["--loss", "1"], "property"),
]

CORRECT = [
    ("ask_until_answered", [*AB, "--goal", "success", "--loss", "1"]),
    ("quorum", ["--agents", "a,b,c", "--goal", "success", "--loss", "1", "--fail", "1"]),
    ("handshake", [*AB, "--loss", "1", "--fail", "1"]),
    ("handshake", [*AB, "--goal", "success", "--loss", "1", "--delay", "1"]),
    ("watch_join", ["--goal", "success"]),
]


KEYS = ["bytes", "values"]  # a state's key: its copy's bytes, or its values (docs/VERIFY.md, *States*)


@pytest.mark.parametrize("keys", KEYS)
@pytest.mark.parametrize(("name", "base", "trigger", "kind"), BUGGY, ids=[f"{b[0]}-{b[3]}" for b in BUGGY])
def test_a_planted_bug_is_found_only_under_its_choice(
    capsys: pytest.CaptureFixture[str],
    tmp_path: Path,
    name: str,
    base: list[str],
    trigger: list[str],
    kind: str,
    keys: str,
) -> None:
    file = DATA / f"{name}.yaml"
    base = [*base, "--keys", keys]
    code, clean = verify(capsys, file, *base, out=tmp_path / "none.jsonl")
    assert (code, clean["verdict"], clean["exhausted"]) == (0, "ok", True), clean["stderr"]
    code, found = verify(capsys, file, *base, *trigger, out=tmp_path / "ce.jsonl")
    assert (code, found["verdict"], found["kind"]) == (1, "violation", kind), found["stderr"]
    assert found["counterexample"] == str(tmp_path / "ce.jsonl")
    assert replay(file, tmp_path / "ce.jsonl", tmp_path / "again.jsonl") in (0, 1)
    assert (tmp_path / "again.jsonl").read_bytes() == (tmp_path / "ce.jsonl").read_bytes()


@pytest.mark.parametrize("keys", KEYS)
@pytest.mark.parametrize(("name", "args"), CORRECT, ids=[f"{c[0]}-{'-'.join(c[1][2:])}" for c in CORRECT])
def test_a_correct_machine_is_proved(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, name: str, args: list[str], keys: str
) -> None:
    code, verdict = verify(capsys, DATA / f"{name}.yaml", *args, "--keys", keys, out=tmp_path / "ce.jsonl")
    assert (code, verdict["verdict"], verdict["kind"], verdict["exhausted"]) == (0, "ok", None, True), verdict
    assert verdict["states"] > 1
    assert not (tmp_path / "ce.jsonl").exists()
