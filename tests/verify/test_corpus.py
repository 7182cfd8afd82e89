"""The corpus (tests/verify/data, listed with what each must give in corpus.yaml): each planted bug
found with its kind, under the choice that shows it and not without; each correct machine proved
with the space exhausted; every counterexample replayed byte for byte."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
import yaml
from verify_run import DATA, replay, verify

CORPUS: dict[str, list[dict[str, Any]]] = yaml.safe_load((DATA / "corpus.yaml").read_text())


def _args(args: list[str]) -> list[str]:
    return [str(DATA / a) if a.endswith(".yaml") else a for a in args]


def _id(case: dict[str, Any]) -> str:
    return "-".join([case["machine"], *(a.removesuffix(".yaml") for a in case.get("trigger", case["args"]))])


BUGGY = CORPUS["buggy"]
CORRECT = CORPUS["correct"]
KEYS = ["bytes", "values"]  # a state's key: its copy's bytes, or its values (docs/VERIFY.md, *States*)


def test_the_corpus_has_planted_bugs_of_every_kind_and_choice() -> None:
    kinds = {c["kind"] for c in BUGGY}
    triggers = {c["trigger"][0] for c in BUGGY}
    assert kinds == {"hang", "error", "failure_outcome", "property"}
    assert {"--loss", "--fail", "--delay", "--stand-in", "--values"} <= triggers
    assert len(BUGGY) + len(CORRECT) >= 35
    assert all((DATA / f"{c['machine']}.yaml").exists() for c in BUGGY + CORRECT)


@pytest.mark.parametrize("keys", KEYS)
@pytest.mark.parametrize("case", BUGGY, ids=[f"{_id(c)}-{c['kind']}" for c in BUGGY])
def test_a_planted_bug_is_found_only_under_its_choice(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, case: dict[str, Any], keys: str
) -> None:
    file = DATA / f"{case['machine']}.yaml"
    base = [*_args(case["args"]), "--keys", keys]
    code, clean = verify(capsys, file, *base, out=tmp_path / "none.jsonl")
    assert (code, clean["verdict"], clean["exhausted"]) == (0, "ok", True), clean["stderr"]
    code, found = verify(capsys, file, *base, *_args(case["trigger"]), out=tmp_path / "ce.jsonl")
    assert (code, found["verdict"], found["kind"]) == (1, "violation", case["kind"]), found["stderr"]
    assert found["counterexample"] == str(tmp_path / "ce.jsonl")
    assert replay(file, tmp_path / "ce.jsonl", tmp_path / "again.jsonl") in (0, 1)
    assert (tmp_path / "again.jsonl").read_bytes() == (tmp_path / "ce.jsonl").read_bytes()


@pytest.mark.parametrize("keys", KEYS)
@pytest.mark.parametrize("case", CORRECT, ids=[_id(c) for c in CORRECT])
def test_a_correct_machine_is_proved(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, case: dict[str, Any], keys: str
) -> None:
    file = DATA / f"{case['machine']}.yaml"
    code, verdict = verify(capsys, file, *_args(case["args"]), "--keys", keys, out=tmp_path / "ce.jsonl")
    assert (code, verdict["verdict"], verdict["kind"], verdict["exhausted"]) == (0, "ok", None, True), verdict
    assert verdict["states"] > 1
    assert not (tmp_path / "ce.jsonl").exists()


def test_a_scoped_counterexample_keeps_its_scopes(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """The schedule names each agent's scope; the replay runs under it (qualified names in the trace)."""
    scoped = ["--agents", "a,b,c,d", "--scope", "p1:a,b", "--scope", "p2:c,d", "--loss", "1"]
    code, _ = verify(capsys, DATA / "pair_hello.yaml", *scoped, out=tmp_path / "ce.jsonl")
    assert code == 1
    lines = (tmp_path / "ce.jsonl").read_text().splitlines()
    assert json.loads(lines[0])["verify"]["scopes"] == {
        "a": ["p1", ["a", "b"]], "b": ["p1", ["a", "b"]], "c": ["p2", ["c", "d"]], "d": ["p2", ["c", "d"]]
    }  # fmt: skip
    sent = {json.loads(line).get("message") for line in lines[1:]} - {None}
    assert sent == {"p1/hello", "p2/hello"}


def test_a_stand_in_script_gives_the_outputs_a_call_may_end_with(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """Two steps with different outputs: each is a choice, named in the schedule with its values."""
    args = ["--stand-in", "sense", "--values", str(DATA / "sense_any.yaml")]
    code, found = verify(capsys, DATA / "measure.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, found["kind"]) == (1, "error")
    schedule = json.loads((tmp_path / "ce.jsonl").read_text().splitlines()[0])["verify"]
    assert schedule["scripts"] == {"sense": {"": [{"distance": 2}, {"distance": 0}]}}
    assert [c["outputs"] for c in schedule["choices"]] == [{"distance": 0}]
