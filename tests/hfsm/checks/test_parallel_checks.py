"""Checks of parallel states (docs/REFERENCE.md#parallel-states), each by code, line, column and message."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from hfsm.errors import UserError
from hfsm.load import load
from hfsm.registry import Registry

Machine = Callable[[str, str], Path]


def found(path: Path) -> list[str]:
    """`file:line:col CODE message` for every finding, errors and warnings."""
    try:
        result = load([path], registry=Registry()).warnings
    except UserError as err:
        result = err.findings
    return [f"{Path(f.file).stem}:{f.line}:{f.col} {f.code} {f.message}" for f in result]


@pytest.fixture
def regions(machine: Machine) -> None:
    machine(
        "explore",
        """
        outcomes: [finished, failed]
        params: {speed: {type: float}}
        outputs: {pose: 1}
        states:
          a: {do: wait, with: {seconds: 1}, on: {done: finished}}
          b: {do: wait, with: {seconds: 1}, on: {done: failed}}
        initial: a
        """,
    )
    machine(
        "detect",
        """
        outcomes: [found, not_found]
        outputs: {pose: 1}
        states:
          a: {do: wait, with: {seconds: 1}, on: {done: found}}
          b: {do: wait, with: {seconds: 1}, on: {done: not_found}}
        """,
    )


def own(path: Path) -> list[str]:
    return [f for f in found(path) if f.startswith(f"{path.stem}:")]


@pytest.mark.usefixtures("regions")
def test_every_problem_of_a_parallel_state_at_its_key(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done, failed, stopped]
        receives: [stop]
        vars: {pose: 0}
        states:
          search:
            parallel:
              explore: {do: explore, with: {sped: 2.0}, save: {pose: pose}}
              detect: {do: detect, save: {pose: pose, where: posx}}
              head: {do: wait, background: true}
            join:
              - else: failed
              - when: {detct: found}
                then: done
              - when: {explore: [finished, faild], head: done}
                then: nowhere
            timer: 300
            on: {stop: stopped, found: done}
        """,
    )
    assert own(path) == [
        "top:7:21 E307 'explore' needs param 'speed'",
        "top:7:37 E302 unknown param 'sped' of 'explore'; did you mean 'speed'?",
        "top:8:35 E325 regions 'explore' and 'detect' both save into var 'pose'",
        "top:8:47 E304 unknown variable 'where'",
        "top:8:54 E305 'detect' has no output 'posx'; did you mean 'pose'?",
        "top:11:9 E311 'else' must be the last rule of 'join'",
        "top:12:16 E321 unknown region 'detct'; did you mean 'detect'?",
        "top:14:36 E323 'explore' has no outcome 'faild'; did you mean 'failed'?",
        "top:14:44 E322 region 'head' is background: it is never awaited, so no rule may name it",
        "top:15:15 E301 unknown target 'nowhere': not a state or outcome",
        "top:16:12 E310 the state has a timer, so 'on' must map 'timeout'",
        "top:17:25 E303 'found' is not a message in 'receives' nor 'timeout' or 'error': a parallel state "
        "leaves on its regions' outcomes by its 'join' rules",
    ]


@pytest.mark.usefixtures("regions")
def test_a_join_that_could_hang_names_the_combination(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done, failed]
        states:
          search:
            parallel:
              explore: {do: explore, with: {speed: 1}}
              detect: {do: detect}
            join:
              - when: {detect: found}
                then: done
              - when: {explore: failed, detect: not_found}
                then: failed
            on: {timeout: failed}
          idle:
            parallel:
              head: {do: wait, background: true}
            join:
              - else: done
        """,
    )
    assert own(path) == [
        "top:7:5 E320 the join can hang: no rule holds when detect=not_found, explore=finished; "
        "add a rule for it, or end 'join' with 'else'",
        "top:12:10 E309 'timeout' is mapped, but the parallel state has no timer",
        "top:13:3 W400 state 'idle' cannot be reached from 'search'",
        "top:14:5 E324 parallel state 'idle' awaits no region: at least one must not be background",
    ]


@pytest.mark.usefixtures("regions")
def test_a_covered_join_and_its_arcs_pass(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done, failed]
        states:
          search:
            parallel:
              explore: {do: explore, with: {speed: 1}}
              detect: {do: detect}
              head: {do: wait, background: true}
            join:
              - when: {detect: found}
                then: approach
              - when: {explore: [finished, failed]}
                then: failed
          approach: {do: wait, with: {seconds: 1}, on: {done: done}}
        """,
    )
    assert own(path) == []


@pytest.mark.usefixtures("regions")
def test_the_uncovered_count_is_told(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done]
        states:
          both:
            parallel:
              a: {do: detect}
              b: {do: detect}
              c: {do: explore, with: {speed: 1}}
            join:
              - {when: {a: found, b: found}, then: done}
        """,
    )
    assert own(path) == [
        "top:8:5 E320 the join can hang: no rule holds when a=found, b=not_found, c=finished "
        "(and 5 more of 8 combinations); add a rule for it, or end 'join' with 'else'"
    ]


def test_a_region_name_is_checked_at_the_name(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done]
        states:
          both:
            parallel:
              Head-1: {do: wait}
            join:
              - else: done
        """,
    )
    assert own(path) == ["top:5:7 E200 bad name 'Head-1': names match ^[a-z][a-z0-9_]*$"]
