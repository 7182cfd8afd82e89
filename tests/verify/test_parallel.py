"""The search with its ticks run by worker processes (`--workers`, hfsm/verify/parallel.py): the
same verdict, kind, exhaustion and counterexample as on one process, and the same states whatever
the number of workers."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml
from verify_run import DATA, MACHINES, verify

from hfsm.cli import verify as verify_cli
from hfsm.verify import parallel, search, step

CORPUS: dict[str, list[dict[str, Any]]] = yaml.safe_load((DATA / "corpus.yaml").read_text())
CASES = [(c["machine"], [*c["args"], *c.get("trigger", [])]) for c in CORPUS["buggy"] + CORPUS["correct"]]


def _args(args: list[str]) -> list[str]:
    return [str(DATA / a) if a.endswith(".yaml") else a for a in args]


@pytest.mark.parametrize(("machine", "args"), CASES, ids=[f"{m}-{'-'.join(a)}" for m, a in CASES])
def test_workers_find_what_one_process_finds(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, machine: str, args: list[str]
) -> None:
    file = DATA / f"{machine}.yaml"
    one_code, one = verify(capsys, file, *_args(args), out=tmp_path / "one.jsonl")
    two_code, two = verify(capsys, file, *_args(args), "--workers", "2", out=tmp_path / "two.jsonl")
    same = ("verdict", "kind", "agent", "exhausted")
    assert (two_code, *(two[k] for k in same)) == (one_code, *(one[k] for k in same)), two["stderr"]
    if one_code == 1:
        assert (tmp_path / "two.jsonl").read_bytes() == (tmp_path / "one.jsonl").read_bytes()
    else:
        assert not (tmp_path / "two.jsonl").exists()


@pytest.mark.parametrize("keys", ["bytes", "values"])
def test_the_states_do_not_depend_on_the_number_of_workers(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch, keys: str
) -> None:
    """Two workers and three explore the very states one process does when it queues no engine
    (every successor run on a copy, as workers run them), in chunks of any size."""
    file = MACHINES / "call_off.yaml"
    args = ["--agents", "r1,r2", "--param", "cycle=1", "--param", "limit=5", "--loss", "1", "--fail", "1",
            "--keys", keys]  # fmt: skip
    monkeypatch.setattr(search, "LIVE", 0)
    _, alone = verify(capsys, file, *args, out=tmp_path / "ce.jsonl")
    monkeypatch.setattr(parallel, "CHUNK", 5)
    counts = {alone["states"]}
    for workers in ("2", "3"):
        code, found = verify(capsys, file, *args, "--workers", workers, out=tmp_path / "ce.jsonl")
        assert (code, found["verdict"], found["exhausted"]) == (0, "ok", True), found["stderr"]
        counts.add(found["states"])
    assert len(counts) == 1 and alone["states"] > 200


def test_a_budget_of_states_stops_the_workers_where_it_stops_one_process(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    file = MACHINES / "move_furniture.yaml"
    args = ["--agents", "r1,r2", "--loss", "1", "--fail", "1", "--max-states", "400"]
    monkeypatch.setattr(search, "LIVE", 0)
    _, alone = verify(capsys, file, *args, out=tmp_path / "ce.jsonl")
    code, found = verify(capsys, file, *args, "--workers", "2", out=tmp_path / "ce.jsonl")
    assert (code, found["verdict"], found["exhausted"]) == (0, "bounded", False)
    assert found["states"] == alone["states"] >= 400


def test_a_worker_that_fails_stops_the_search_with_its_error(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(*args: Any) -> None:
        raise ValueError("a tick that cannot run")

    monkeypatch.setattr(step, "next_state", broken)  # the workers are forked with it; the search runs no tick
    with pytest.raises(RuntimeError, match="a tick that cannot run"):
        verify_cli._main(verify_cli.build_parser().parse_args(
            [str(DATA / "handshake.yaml"), "--agents", "a,b", "--loss", "1", "--workers", "2",
             "--out", str(tmp_path / "ce.jsonl")]))  # fmt: skip


@pytest.mark.parametrize("workers", ["0", "-1", "two"])
def test_workers_must_be_one_or_more(capsys: pytest.CaptureFixture[str], tmp_path: Path, workers: str) -> None:
    code, found = verify(capsys, DATA / "handshake.yaml", "--workers", workers, out=tmp_path / "ce.jsonl")
    assert code == 2
    assert "--workers" in found["stderr"] and "Traceback" not in found["stderr"]
    assert f"{workers!r}: a whole number >= 1" in found["stderr"]


def test_workers_stopped_at_a_violation_leave_nothing_on_stderr(tmp_path: Path) -> None:
    """The search stops at the first violation while its workers still run chunks it no longer
    needs: they end quietly, however far they got."""
    import subprocess
    import sys

    done = subprocess.run(
        [sys.executable, "-m", "hfsm.cli.verify", str(MACHINES / "move_furniture.yaml"), "--agents", "r1,r2",
         "--loss", "1", "--fail", "1", "--bound", "5", "--workers", "2", "--json",
         "--out", str(tmp_path / "ce.jsonl")],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert done.returncode == 1, done.stderr
    assert '"kind": "hang"' in done.stdout
    assert "Traceback" not in done.stderr and "Error" not in done.stderr
