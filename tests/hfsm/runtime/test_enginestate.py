"""An engine's state between ticks (hfsm/runtime/enginestate.py): `restore_engine(e.snapshot())` is
`e` again, a copy (a pickle, as hfsm-verify makes one) is one engine whose parts are wired to its
own clock and team, and the same choices from a state, its copy and its restored engine lead to the
same states."""

from __future__ import annotations

import itertools
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from verify_run import DATA, prefixes, reached_states

from hfsm.builtins.barrier import Barrier
from hfsm.runtime.clock import RunClock
from hfsm.runtime.engine import Engine, restore_engine
from hfsm.runtime.team import Team
from hfsm.trace import ListTrace
from hfsm.verify.choices import Chooser
from hfsm.verify.step import next_state
from hfsm.world import NullWorld

RUNS = [  # a barrier of three, messages late and lost, a failure; scoped pairs
    ("quorum.yaml", ["--agents", "a,b,c", "--loss", "1", "--fail", "1", "--delay", "1"]),
    ("handshake.yaml", ["--agents", "a,b", "--loss", "1", "--fail", "1", "--delay", "1"]),
    ("pair_hello.yaml", ["--agents", "a,b,c,d", "--scope", "p1:a,b", "--scope", "p2:c,d", "--loss", "1"]),
]


@pytest.fixture(scope="module")
def reached(tmp_path_factory: pytest.TempPathFactory) -> list[tuple[bytes, Any]]:
    runs = [(DATA / file, args) for file, args in RUNS]
    return reached_states(runs, tmp_path_factory.mktemp("enginestate"), each=40, max_states=200)


def _everything(root: Any, shared: dict[int, Any]) -> list[Any]:
    """Every object reachable from `root` that the state's copy holds (not the program's)."""
    seen: dict[int, Any] = {}
    stack = [root]
    while stack:
        obj = stack.pop()
        if id(obj) in seen or id(obj) in shared or isinstance(obj, str | int | float | bool | type | None):
            continue
        seen[id(obj)] = obj
        if isinstance(obj, dict):
            stack.extend(obj.keys())
            stack.extend(obj.values())
        elif isinstance(obj, list | tuple | set | frozenset):
            stack.extend(obj)
        else:
            stack.extend(getattr(obj, n) for n in getattr(type(obj), "__slots__", ()) if hasattr(obj, n))
            stack.extend(getattr(obj, "__dict__", {}).values())
    return list(seen.values())


def test_a_copy_is_one_engine_wired_to_its_own_clock_and_team(reached: list[tuple[bytes, Any]]) -> None:
    assert len(reached) > 40
    waiting = 0
    for data, found in reached:
        engine = found.snaps.load(data)
        objects = _everything(engine, {id(o): o for o in found.snaps.objects})
        assert [o for o in objects if isinstance(o, RunClock)] == [engine.clock]
        assert [o for o in objects if isinstance(o, Team)] == [engine.team]
        assert all(a.clock is engine.clock for a in engine.agents)
        assert engine.team.clock is engine.clock and engine.loop.clock is engine.clock
        for barrier in (o for o in objects if isinstance(o, Barrier)):
            waiting += 1
            assert barrier.team is engine.team
        again = found.snaps.dump(engine)
        assert found.snaps.dump(found.snaps.load(again)) == again
    assert waiting > 0  # quorum's agents wait in a barrier


@settings(max_examples=20, deadline=None)
@given(index=st.integers(0, 10**6))
def test_restoring_a_snapshot_gives_the_same_engine_and_the_same_futures(
    reached: list[tuple[bytes, Any]], index: int
) -> None:
    data, found = reached[index % len(reached)]
    engine = found.snaps.load(data)
    state = engine.snapshot()
    restored = restore_engine(state)
    assert restored.snapshot() == state
    assert restored.team is engine.team and restored.clock is engine.clock
    assert [a.radio for a in restored.agents] == state.radios
    chooser: Chooser = found.chooser
    for prefix in itertools.islice(prefixes(found, data), 6):
        after = []
        for make in (
            lambda: found.snaps.load(data),
            lambda: restore_engine(found.snaps.load(data).snapshot()),
            lambda: found.snaps.load(found.snaps.dump(found.snaps.load(data))),
        ):
            one = make()
            chooser.begin(prefix)
            ended = next_state(one, one.world, chooser, 10**9)
            after.append((ended and ended.why, [c.choice for c in chooser.made], found.snaps.dump(one)))
        assert after[0] == after[1] == after[2]


def test_an_engine_writing_a_trace_has_no_snapshot() -> None:
    engine = Engine([], NullWorld(), 0.05, ListTrace())
    with pytest.raises(ValueError, match="trace"):
        engine.snapshot()


def test_a_copy_writes_what_never_changes_as_references(reached: list[tuple[bytes, Any]]) -> None:
    """Classes, the function that makes an engine again and attribute names are in the table both
    ends of a copy hold (hfsm/verify/snapshot.py): never in a state's bytes, and a load gives the
    table's very objects."""
    for data, found in reached:
        assert b"hfsm.runtime" not in data and b"restore_engine" not in data
        assert b"state_deadline" not in data and b"vars_shown" not in data
        engine = found.snaps.load(data)
        seed = {id(o) for o in found.snaps.seed}
        assert all(id(name) in seed for a in engine.agents for name in vars(a))
        state = engine.snapshot()
        assert all(id(o.__class__) in seed for o in (*state.agents, state.world, state.clock, state.team))
        assert all(id(type(a.root)) in seed for a in engine.agents if a.root is not None)
