"""Every SPEC example and rule with a run: `hfsm-run --world none --json`, compared with what the
SPEC's text says (ticks, outcomes, outputs, exit codes). The files are in tests/spec/cases/; each
says which sentence of the SPEC it runs."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from spec.conformance import hfsm_run, paired

NULL: dict[str, Any] = {}


def one(outcome: str | None, time: float, outputs: dict[str, Any] = NULL) -> dict[str, Any]:
    return {"outcome": outcome, "outputs": dict(outputs), "time": time}


def failed(time: float) -> dict[str, Any]:
    return {"outcome": None, "outputs": {}, "time": time, "failed": "--fail"}


RUNS: dict[str, tuple[list[str], int, dict[str, Any]]] = {
    # section 3: the choice state as written
    "role": (["--agents", "a,b"], 0, {"agents": {"a": one("leader", 0.0), "b": one("assistant", 0.0)}}),
    # section 5: spans, timers, the watchdog
    "span": ([], 0, one("done", 0.65, {"log": [0.65]})),
    "watchdog": ([], 0, one("timeout", 0.5, {"t": 0.5})),
    # section 4: an unmapped error reaches the top
    "unmapped_error": (
        [],
        1,
        {**one(None, 0.1), "error": "unmapped_error/outer/divide: division by zero in '1 // vars.n'"},
    ),
    # section 6: early messages, message arcs before wait_for, send to all, unknown agents
    "early": (["--agents", "a,b"], 0, {"agents": {"a": one("sent", 0.0), "b": one("heard", 0.2)}}),
    "messages": (
        ["--agents", "a,b"],
        0,
        {"agents": {x: one("bad", 0.05, {"got": "a", "who": "a"}) for x in "ab"}},
    ),
    # section 7: literal conditions, values as text
    "literal_if": ([], 0, one("done", 0.0, {"path": ["two"]})),
    "text": (
        [],
        0,
        one(
            "done",
            0.0,
            {
                "text": '2 0.1 1e+16 true false null s [1, "x"] {"k": 1.5} 3 1.5',
                "typed": [2.0, None, True],
            },
        ),
    ),
    # section 10: --max-time, blocked forever
    "slow": (["--max-time", "1.99"], 0, one("done", 2.0)),
    "stuck": ([], 1, {**one(None, 0.0), "error": "blocked forever: robot in stuck/listen"}),
    # section 11: the example as written, and its rules
    "search": (
        ["--agents", "finder,miss,lost,stuck"],
        0,
        {
            "agents": {
                "finder": one("found", 0.5, {"pose": [1, 2]}),
                "miss": one("failed", 1.0, {"pose": [1, 2]}),  # the second rule, once `explore` ends
                "lost": one("failed", 2.0, {"pose": [1, 2]}),
                "stuck": one("failed", 300.0, {"pose": None}),  # the state's timer
            }
        },
    ),
    "search_stopped": (
        ["--agents", "boss,finder,stuck"],
        0,
        {
            "agents": {
                "boss": one("told", 0.2, {"pose": None}),
                "finder": one("stopped", 0.25, {"pose": None}),
                "stuck": one("stopped", 0.25, {"pose": None}),
            }
        },
    ),
    "regions_order": ([], 0, one("done", 0.5, {"x": 5, "t": 0.0})),
    "join_else": ([], 0, one("other", 0.3, {"a": 1, "b": 2, "c": 0})),
    "parallel_early": (
        ["--agents", "a,b"],
        0,
        {
            "agents": {
                "a": one("sent", 0.2, {"one": None, "two": None}),
                "b": one("stopped", 0.6, {"one": 1, "two": 2}),
            }
        },
    ),
    "region_error": ([], 0, one("broken", 0.1)),
    "region_unmapped": (
        [],
        1,
        {**one(None, 0.1), "error": "region_unmapped/p/bad/divide: division by zero in '1 // vars.n'"},
    ),
    # section 12: watches, state.time, machine.time
    "watches": ([], 0, one("done", 2.0, {"seen": [0.3, 0.0]})),
    "watch_self": ([], 0, one("gave_up", 0.5)),
    # section 13: the example as written, and the edges of retries
    "navigate": ([], 0, one("done", 6.0, {"tried": 3})),
    "retry_edges": ([], 0, one("halted", 1.45, {"tried": [0.7]})),
    "attempt": ([], 0, one("gave_up", 2.25)),
    # section 14: barriers
    "meet": (
        ["--agents", "a,b,c"],
        0,
        {
            "agents": {
                a: one("done", 1.0, {"heard": [x for x in "abc" if x != a], "times": [0.35, 1.0]})
                for a in "abc"
            }
        },
    ),
    "barrier_errors": (["--agents", "a,b,c"], 0, {"agents": {a: one("broken", 0.0) for a in "abc"}}),
    "team": (
        ["--agents", "a,b,c"],
        0,
        {
            "agents": {
                "a": one("lifted", 2.55, {"partners": ["b"]}),
                "b": one("lifted", 2.55, {"partners": ["a"]}),
                "c": one("lifted", 3.55, {"partners": ["a", "b"]}),  # held both notices on arrival
            }
        },
    ),
}


@pytest.mark.parametrize("name", sorted(RUNS))
def test_a_spec_example_runs_as_the_spec_says(
    name: str, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    args, code, expected = RUNS[name]
    ran = hfsm_run(capsys, tmp_path, name, args)
    assert (ran.code, ran.result) == (code, expected), ran.err
    assert paired(ran.records), "every enter has its exit"
    again = hfsm_run(capsys, tmp_path, name, args)
    assert again.records == ran.records, "same seed, same trace"


FAILS: dict[str, tuple[list[str], int, dict[str, Any]]] = {
    "one": (
        ["--fail", "c@1"],
        0,
        {
            "a": one("lifted", 2.55, {"partners": ["b"]}),
            "b": one("lifted", 2.55, {"partners": ["a"]}),
            "c": failed(1.0),
        },
    ),
    "all": (
        ["--fail", "c@1", "--fail", "a@0.5", "--fail", "b@0.2"],
        1,
        {"a": failed(0.5), "b": failed(0.2), "c": failed(1.0)},
    ),
    "at_start": (
        ["--fail", "a@0"],  # never starts; b waits in the barrier for c
        0,
        {
            "a": failed(0.0),
            "b": one("lifted", 3.55, {"partners": ["c"]}),
            "c": one("lifted", 3.55, {"partners": ["b"]}),
        },
    ),
}


@pytest.mark.parametrize("case", sorted(FAILS))
def test_agents_that_fail(case: str, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """docs/REFERENCE.md#agents-that-fail: a failed agent's entry, the exit code decided by the others, its `failed` record."""
    args, code, agents = FAILS[case]
    ran = hfsm_run(capsys, tmp_path, "team", ["--agents", "a,b,c", *args])
    assert ran.code == code
    assert ran.result["agents"] == agents
    assert ("error" in ran.result) == (code == 1)
    for name, entry in agents.items():
        if "failed" in entry:
            assert [r["t"] for r in ran.records if r["agent"] == name and r["kind"] == "failed"] == [
                entry["time"]
            ]
    assert paired(ran.records)
