"""A trace shows a machine's vars as they change: a record's `vars` holds those assigned since the
last one shown (all at the machine's start), never the machine's `untraced` ones
(docs/LANGUAGE.md#statuses-and-long-runs-sends-keep-our-extension)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.cli.run import main as hfsm_run
from tests.helpers import execute, write

STEPS = """
vars: {n: 0, hold: {}, note: ""}
untraced: [hold]
outcomes: [done]
outputs: {n: "${vars.n}", note: "${vars.note}"}
states:
  both:
    do: set
    with: {n: 1, hold: {a: 1}}
    on: {done: quiet}
  quiet:
    do: set
    with: {hold: {a: 2}}
    on: {done: note}
  note:
    do: set
    with: {note: x}
    on: {done: done}
"""


def _shown(records: list[dict[str, Any]]) -> list[tuple[str, str, dict[str, Any]]]:
    return [(r["kind"], r["path"][-1], r["vars"]) for r in records if "vars" in r]


def test_a_record_shows_the_vars_that_changed_and_never_an_untraced_one(tmp_path: Path) -> None:
    _, records = execute(write(tmp_path, "steps", STEPS))
    assert _shown(records) == [
        ("enter", "both", {"n": 0, "note": ""}),
        ("event", "both", {"n": 1}),
        ("event", "note", {"note": "x"}),
    ]


def test_the_jsonl_trace_writes_the_same_vars(tmp_path: Path) -> None:
    path = write(tmp_path, "steps", STEPS)
    trace = tmp_path / "t.jsonl"
    assert hfsm_run([str(path), "--world", "none", "--quiet", "--trace", str(trace)]) == 0
    lines = [json.loads(line) for line in trace.read_text().splitlines()]
    _, records = execute(path)
    assert _shown(lines) == _shown(records)


NAMES = ("a", "b", "c")


def _machine(steps: list[dict[str, int]], quiet: list[str]) -> str:
    states = []
    for i, values in enumerate(steps):
        target = f"s{i + 1}" if i + 1 < len(steps) else "done"
        assigned = ", ".join(f"{k}: {v}" for k, v in values.items())
        states.append(f"  s{i}:\n    do: set\n    with: {{{assigned}}}\n    on: {{done: {target}}}\n")
    outputs = ", ".join(f'{k}: "${{vars.{k}}}"' for k in NAMES)
    return (
        "vars: {a: 0, b: 0, c: 0}\n"
        f"untraced: [{', '.join(quiet)}]\n"
        "outcomes: [done]\n"
        f"outputs: {{{outputs}}}\n"
        "states:\n" + "".join(states)
    )


@settings(max_examples=40, deadline=None)
@given(
    steps=st.lists(st.dictionaries(st.sampled_from(NAMES), st.integers(0, 9), min_size=1), min_size=1, max_size=6),
    quiet=st.lists(st.sampled_from(NAMES), unique=True),
)
def test_adding_up_the_shown_vars_gives_the_traced_vars_at_every_step(
    tmp_path_factory: Any, steps: list[dict[str, int]], quiet: list[str]
) -> None:
    path = write(tmp_path_factory.mktemp("m"), "m", _machine(steps, quiet))
    result, records = execute(path)
    known: dict[str, Any] = {}
    for record in records:
        if "vars" in record:
            assert not set(record["vars"]) & set(quiet)
            known.update(record["vars"])
    traced = {k: v for k, v in result.agents["robot"].outputs.items() if k not in quiet}
    assert known == traced
