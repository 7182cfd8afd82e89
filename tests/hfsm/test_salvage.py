"""The schema's errors no longer hide the rest: the checks run on what is well formed, and what only
follows from a part left out is not reported."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from hfsm.load import check_files
from hfsm.registry import Registry

Machine = Callable[[str, str], Path]


def codes(path: Path) -> list[tuple[int, str]]:
    _, _, findings = check_files([path], [], Registry())
    return [(f.line, f.code) for f in findings]


def test_a_file_with_many_problems_shows_them_all(machine: Machine) -> None:
    path = machine(
        "m",
        """\
outcomes: [done, failed]
vars: {count: 0}
states:
  start:
    do: wiat
    timeout: 5
    on: {done: serch}
  search:
    do: wait
    with: {secs: 2}
    on: {done: don}
  pick:
    choose:
      - if: vars.cont > 1
        then: done
      - els: failed
""",
    )
    assert codes(path) == [
        (5, "E300"), (6, "E200"), (7, "E301"), (10, "E302"), (11, "E301"), (14, "E314"), (16, "E200")
    ]  # fmt: skip


def test_a_target_naming_a_state_left_out_is_not_unknown(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  a:\n    on: {done: b}\n  b: {do: wait, on: {done: a}}\n")
    assert codes(path) == [(4, "E200")]  # `a` lacks `do`; `b`'s arc to it is not reported


def test_a_mapped_timeout_whose_timer_was_refused_is_not_reported(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  a: {do: wait, timer: -1, on: {done: done, timeout: done}}\n")
    assert codes(path) == [(3, "E200")]


def test_a_file_lacking_its_own_keys_shows_the_schemas_findings_only(machine: Machine) -> None:
    path = machine("m", "states:\n  a: {do: wiat, on: {done: done}}\n")
    assert codes(path) == [(1, "E200")]


def test_a_lone_unknown_key_stands_for_the_lone_missing_one(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  a:\n    dp: wait\n    on: {done: done}\n")
    _, _, findings = check_files([path], [], Registry())
    assert [f.message for f in findings] == ["unknown key 'dp'; did you mean 'do'?"]
