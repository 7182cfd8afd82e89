"""An engine the search no longer needs is discarded (hfsm/verify/step.py `discard`): what is left of
it is freed by reference counts, no cycle left for the collector, whatever the state held (regions
of a parallel state, barriers waiting, scopes, messages in flight, stand-ins)."""

from __future__ import annotations

import gc
from pathlib import Path
from typing import Any

import pytest
from verify_run import DATA, MACHINES, reached_states, verify

from hfsm.verify import search
from hfsm.verify.step import discard

RUNS = [
    (DATA / "quorum.yaml", ["--agents", "a,b,c", "--loss", "1", "--fail", "1", "--delay", "1"]),
    (DATA / "pair_hello.yaml", ["--agents", "a,b,c,d", "--scope", "p1:a,b", "--scope", "p2:c,d", "--loss", "1"]),
    (DATA / "watch_join.yaml", ["--goal", "success"]),
    (MACHINES / "elect_leader.yaml", ["--agents", "r1,r2", "--param", "distance=1", "--param", "limit=5",
                                      "--loss", "1", "--fail", "1"]),
]  # fmt: skip


@pytest.fixture(scope="module")
def reached(tmp_path_factory: pytest.TempPathFactory) -> list[tuple[bytes, Any]]:
    return reached_states(RUNS, tmp_path_factory.mktemp("discard"), each=60, max_states=300)


def _cyclic_garbage(make: Any) -> list[Any]:
    """What the collector finds unreachable after `make()` runs, with collections held off meanwhile."""
    gc.collect()
    gc.disable()
    try:
        make()
        gc.set_debug(gc.DEBUG_SAVEALL)
        gc.collect()
        return list(gc.garbage)
    finally:
        gc.set_debug(0)
        gc.garbage.clear()
        gc.enable()


def test_a_discarded_engine_leaves_no_cycle(reached: list[tuple[bytes, Any]]) -> None:
    assert len(reached) > 100
    parallel = 0
    for data, found in reached:
        engine = found.snaps.load(data)
        parallel += any(a.root is not None and a.root.below.__class__ is list for a in engine.agents)
        del engine
        assert _cyclic_garbage(lambda: discard(found.snaps.load(data))) == []  # noqa: B023
    assert parallel > 0  # elect_leader's parallel state: regions


def test_an_engine_not_discarded_is_a_cycle(reached: list[tuple[bytes, Any]]) -> None:
    """The test above can fail: an engine dropped as it is leaves its cycles to the collector."""
    data, found = reached[0]
    assert _cyclic_garbage(lambda: found.snaps.load(data))


def test_discarding_changes_no_verdict_nor_count(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """The search discards engines as it goes: the same states as when it leaves them to the collector."""
    args = ["--agents", "a,b,c", "--goal", "success", "--loss", "1", "--fail", "1"]
    _, kept = _verify_keeping(capsys, tmp_path, args)
    code, discarded = verify(capsys, DATA / "quorum.yaml", *args, out=tmp_path / "ce.jsonl")
    assert code == 0 and discarded["exhausted"]
    assert (discarded["states"], discarded["verdict"]) == (kept["states"], kept["verdict"])


def _verify_keeping(capsys: pytest.CaptureFixture[str], tmp_path: Path, args: list[str]) -> tuple[int, Any]:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(search, "discard", lambda engine: None)
        return verify(capsys, DATA / "quorum.yaml", *args, out=tmp_path / "kept.jsonl")
