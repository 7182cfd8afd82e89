"""A state's key (hfsm.verify.canon): equal situations share it however their objects were made,
and however late they happen; different ones do not; the search merges what shares one."""

from __future__ import annotations

import itertools
import os
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from verify_run import DATA, NoCapture, prefixes, verify

from hfsm.load import load
from hfsm.runtime.agent import Frame
from hfsm.verify import search, snapshot
from hfsm.verify.build import unobserved
from hfsm.verify.canon import TICKS, Keys
from hfsm.verify.step import next_state


class _Unmerged(Keys):
    """Keys that never repeat: a search without merging."""

    def __call__(self, engine: Any) -> bytes:
        return os.urandom(16)


def test_two_paths_to_one_situation_are_explored_once(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    args = ("--stand-in", "pick", "--keys", "values")
    code, merged = verify(capsys, DATA / "fork.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, merged["exhausted"]) == (0, True)
    # tick 0: `pick` ends left, or right (2 states); both enter `settle` in tick 1 (1 state, merged);
    # the run ends (1). Without merging the two paths stay apart: 2 + 2 + 2.
    assert merged["states"] == 4
    monkeypatch.setattr(search, "Keys", _Unmerged)
    code, apart = verify(capsys, DATA / "fork.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, apart["states"]) == (0, 6)


COUNTS = [  # states explored with keys as bytes, and by value (a state's first successor runs on it, not on
    # a copy, so its bytes may differ from a copy's: quorum 264 by bytes, where copies only gave 255);
    # failures of agents whose turn changes nothing put off: handshake 847 and 689, quorum 264 and 211 before
    ("handshake", ["--agents", "a,b", "--loss", "1", "--fail", "1"], 845, 687),
    ("quorum", ["--agents", "a,b,c", "--goal", "success", "--loss", "1", "--fail", "1"], 224, 201),
    ("ask_until_answered", ["--agents", "a,b", "--goal", "success", "--loss", "1"], 14, 11),
    ("watch_join", ["--goal", "success"], 20, 20),
]


@pytest.mark.parametrize(("name", "args", "as_bytes", "by_value"), COUNTS, ids=[c[0] for c in COUNTS])
def test_the_state_count_of_a_small_machine_is_pinned(
    capsys: pytest.CaptureFixture[str],
    tmp_path: Path,
    name: str,
    args: list[str],
    as_bytes: int,
    by_value: int,
) -> None:
    """By value, fewer: a copy's bytes tell apart states that differ only in caches (a frame's
    expression scope made or not, statistics, whether the trace showed the vars), or in which equal
    strings are one object (docs/VERIFY.md, *States*)."""
    code, verdict = verify(capsys, DATA / f"{name}.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, verdict["exhausted"], verdict["states"]) == (0, True, as_bytes)
    code, verdict = verify(
        capsys, DATA / f"{name}.yaml", *args, "--keys", "values", out=tmp_path / "ce.jsonl"
    )
    assert (code, verdict["exhausted"], verdict["states"]) == (0, True, by_value)


def _states(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> tuple[list[Any], Any]:
    """Engines the search of the paper's handshake reaches (copies, as bytes), and its snapshots."""
    found: list[bytes] = []
    kept: dict[str, Any] = {}
    visit = search.Search.visit

    def recording(self: search.Search, engine: Any, ended: Any, parent: int) -> bool:
        kept["search"] = self
        if ended is None and engine.running and len(found) < 60:
            found.append(self.snaps.dump(engine))
        return visit(self, engine, ended, parent)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(search.Search, "visit", recording)
        patch.setattr(snapshot.Snapshots, "close", lambda self: None)
        args = ["--agents", "a,b", "--loss", "1", "--fail", "1", "--delay", "1", "--max-states", "300"]
        args += ["--keys", "values"]
        verify(capsys, DATA / "handshake.yaml", *args, out=tmp_path / "ce.jsonl")
    return found, kept["search"]  # its snapshots left open: the tests below load them


def _shift(engine: Any, by: int, shared: dict[int, int]) -> None:
    """Every tick of a (copied) engine moved `by` ticks later."""
    seen: set[int] = set()
    stack: list[Any] = [engine]
    while stack:
        obj = stack.pop()
        if id(obj) in seen or id(obj) in shared or isinstance(obj, str | int | float | bool | type(None)):
            continue
        seen.add(id(obj))
        if isinstance(obj, dict):
            stack.extend(obj.values())
            continue
        if isinstance(obj, list | tuple | set):
            stack.extend(obj)
            continue
        names = {*getattr(type(obj), "__slots__", ()), *getattr(obj, "__dict__", {})}
        for name in names:
            value = getattr(obj, name, None)
            ticks = TICKS.get(type(obj).__name__, frozenset()) | {"deadline"}
            if name in ticks and type(value) is int:
                object.__setattr__(obj, name, value + by)  # a Message is frozen
            elif not (type(obj).__name__ == "Frame" and name in ("agent", "up")):
                stack.append(value)
    engine.world.flying = [(t + by, n, m) for t, n, m in engine.world.flying]
    engine.world.tick = engine.tick


class Reached(tuple[list[bytes], Any]):
    def __repr__(self) -> str:
        return f"<{len(self[0])} states of the handshake>"


@pytest.fixture(scope="module")
def reached(tmp_path_factory: pytest.TempPathFactory) -> Reached:
    capsys: Any = NoCapture()
    return Reached(_states(capsys, tmp_path_factory.mktemp("canon")))


def test_a_copy_has_the_key_of_its_original(reached: tuple[list[bytes], Any]) -> None:
    datas, found = reached
    assert len(datas) > 20
    for data in datas:
        engine = found.snaps.load(data)
        again = found.snaps.load(found.snaps.dump(engine))
        assert found.key(engine) == found.key(again)


def test_different_situations_have_different_keys(reached: tuple[list[bytes], Any]) -> None:
    datas, found = reached
    engine = found.snaps.load(datas[-1])
    before = found.key(engine)
    frame: Frame = next(a.root for a in engine.agents if a.root is not None)
    frame.vars["other"] = "someone"
    assert found.key(engine) != before
    engine = found.snaps.load(datas[-1])
    frame = next(a.root for a in engine.agents if a.root is not None)
    assert frame.deadline is not None  # the handshake's timer: 30 s
    frame.deadline += 1
    assert found.key(engine) != before
    engine = found.snaps.load(datas[-1])
    engine.world.loss = 1 - engine.world.loss
    assert found.key(engine) != before


@settings(max_examples=25, deadline=None)
@given(index=st.integers(0, 59), by=st.integers(1, 5000))
def test_a_situation_later_in_time_has_the_same_key_and_the_same_futures(
    reached: tuple[list[bytes], Any], index: int, by: int
) -> None:
    """What the key leaves out (the absolute tick) changes nothing that happens next: the same
    choices from a state and from that state moved later give states moved as much."""
    datas, found = reached
    data = datas[index % len(datas)]
    early, late = found.snaps.load(data), found.snaps.load(data)
    _shift(late, by, found.key.shared)
    assert found.key(early) == found.key(late)
    chooser = found.chooser
    for prefix in itertools.islice(prefixes(found, data), 8):
        early, late = found.snaps.load(data), found.snaps.load(data)
        _shift(late, by, found.key.shared)
        results = []
        for engine in (early, late):
            chooser.begin(prefix)
            ended = next_state(engine, engine.world, chooser, 10**9)
            results.append((ended and ended.why, engine.running))
        assert results[0] == results[1]
        assert late.tick == early.tick + by
        assert found.key(early) == found.key(late)


def test_a_situation_met_again_later_is_explored_again(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """`spin` comes back to the same situation every second, later each time: merged into the
    first, its run would seem to end nowhere; explored again, it reaches the bound."""
    args = ("--bound", "5", "--keys", "values")
    code, verdict = verify(capsys, DATA / "spin.yaml", *args, out=tmp_path / "ce.jsonl")
    assert (code, verdict["kind"]) == (1, "hang")
    assert "still running at the bound (5 s)" in verdict["stderr"]
    code, verdict = verify(capsys, DATA / "spin.yaml", "--param", "laps=0", out=tmp_path / "ok.jsonl")
    assert (code, verdict["verdict"], verdict["exhausted"]) == (0, "ok", True)


def test_a_frames_times_are_left_out_of_keys_only_where_nothing_reads_them() -> None:
    spin = load([DATA / "spin.yaml"])
    assert unobserved(spin, False) == {"started", "entered"}
    assert unobserved(spin, True) == {"started"}  # a `left_within` property reads when it was entered
    assert "entered" not in unobserved(load([DATA / "watch_join.yaml"], libs=[DATA]), False)  # state.time


def test_the_inputs_values_are_shared_by_states_not_copied(reached: Reached) -> None:
    datas, found = reached
    engine = found.snaps.load(datas[-1])
    given = engine.world.given
    named = [n for n in given.values if "_" in n]  # names no state holds otherwise (`start` is in `started`)
    assert named and all(name.encode() not in data for name in named for data in datas)
    assert found.snaps.load(datas[0]).world.given is given
    for name, value in given.values.items():
        if isinstance(value, list | dict):
            assert engine.world.read_input("a", name, 0) is not value  # each state's own to change
