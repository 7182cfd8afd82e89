"""Every check of docs/REFERENCE.md#hfsm-run, by its stable code, at its position."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from hfsm.errors import Severity, UserError
from hfsm.load import load
from hfsm.primitive import Context, primitive
from hfsm.registry import Registry

Machine = Callable[[str, str], Path]


@primitive(outcomes=["ok", "failure"], failures=["failure"], outputs=["value"])
def probe(ctx: Context, *, gain: float, label: str = "x") -> str:
    return "ok"


def findings(path: Path, strict: bool = False) -> list[str]:
    try:
        loaded = load([path], registry=Registry([probe]), strict=strict)
    except UserError as err:
        return [f"{f.line}:{f.col} {f.code} {f.message}" for f in err.findings]
    return [f"{f.line}:{f.col} {f.code} {f.message}" for f in loaded.warnings]


def codes(path: Path, strict: bool = False) -> list[str]:
    return [f.split()[1] for f in findings(path, strict)]


GOOD = """
    outcomes: [done]
    states:
      a: {do: wait, with: {seconds: 1}, on: {done: done}}
"""


@pytest.mark.parametrize(
    ("body", "code"),
    [
        ("outcomes: [error]\nstates:\n  a: {do: wait, on: {done: error}}\n", "E202"),
        ("outcomes: [done]\nreceives: [timeout]\nstates:\n  a: {do: wait, on: {done: done}}\n", "E202"),
        ("outcomes: [done]\nstates:\n  done: {do: wait, on: {done: done}}\n", "E315"),
        ("outcomes: [done]\ninitial: b\nstates:\n  a: {do: wait, on: {done: done}}\n", "E316"),
        ("outcomes: [done]\nfailures: [oops]\nstates:\n  a: {do: wait, on: {done: done}}\n", "E318"),
        ("outcomes: [done]\nvars: {hold: 0}\nuntraced: [hodl]\nstates:\n  a: {do: wait, on: {done: done}}\n", "E333"),
        ("outcomes: [done]\nstates:\n  a: {do: wait, on: {done: nowhere}}\n", "E301"),
        ("outcomes: [done]\nstates:\n  a: {do: wiat, on: {done: done}}\n", "E300"),
        ("outcomes: [done]\nstates:\n  a: {do: wait, with: {secs: 1}, on: {done: done}}\n", "E302"),
        ("outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: fast}, on: {done: done}}\n", "E306"),
        ("outcomes: [done]\nstates:\n  a: {do: probe, on: {ok: done, failure: done}}\n", "E307"),
        ("outcomes: [done]\nstates:\n  a: {do: probe, with: {gain: 1}, on: {ok: done}}\n", "E308"),
        ("outcomes: [done]\nstates:\n  a: {do: wait, on: {done: done, timeout: done}}\n", "E309"),
        ("outcomes: [done]\nstates:\n  a: {do: wait, timer: 1, on: {done: done}}\n", "E310"),
        ("outcomes: [done]\nstates:\n  a: {do: wait, on: {done: done, go: done}}\n", "E303"),
        ("outcomes: [done]\nany: {go: done}\nstates:\n  a: {do: wait, on: {done: done}}\n", "E303"),
        ("outcomes: [done]\nreceives: [done]\nstates:\n  a: {do: wait, on: {done: done}}\n", "E317"),
        ("outcomes: [done]\nvars: {x: 1}\nstates:\n  a: {do: set, with: {y: 2}, on: {done: done}}\n", "E304"),
        (
            "outcomes: [done]\nvars: {x: 1}\nstates:\n  a: {do: wait, save: {y: v}, on: {done: done}}\n",
            "E304",
        ),
        (
            "outcomes: [done]\nvars: {x: 1}\nstates:\n  a: {do: wait, save: {x: v}, on: {done: done}}\n",
            "E305",
        ),
        ("outcomes: [done]\nstates:\n  a:\n    choose:\n      - {if: 'true', then: done}\n", "E311"),
        (
            "outcomes: [done]\nstates:\n  a:\n    choose:\n      - {else: done}\n      - {if: 'true', then: done}\n",
            "E311",
        ),
        (
            "outcomes: [done]\nstates:\n  a:\n    choose:\n      - {if: 'true', then: b}\n      - {else: b}\n"
            "  b:\n    choose:\n      - {if: 'true', then: a}\n      - {else: done}\n",
            "E313",
        ),
        (
            "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: '${vars.nope}'}, on: {done: done}}\n",
            "E314",
        ),
        (
            "outcomes: [done]\nstates:\n  a:\n    choose:\n      - {if: 'import os', then: done}\n      - {else: done}\n",
            "E314",
        ),
        (
            "outcomes: [done]\ntimer: '${vars.x}'\nvars: {x: 1}\nstates:\n  a: {do: wait, on: {done: done}}\n",
            "E314",
        ),
        (
            "outcomes: [done]\nparams: {p: {type: int, default: 1.5}}\nstates:\n  a: {do: wait, on: {done: done}}\n",
            "E306",
        ),
        ("outcomes: [done]\nstates:\n  a: {do: send, with: {message: timeout}, on: {sent: done}}\n", "E202"),
        ("outcomes: [done]\nstates:\n  a: {do: send, with: {message: Bad}, on: {sent: done}}\n", "E201"),
        ("name: other\noutcomes: [done]\nstates:\n  a: {do: wait, on: {done: done}}\n", "E203"),
    ],
)
def test_error(machine: Machine, body: str, code: str) -> None:
    assert code in codes(machine("m", body))


def test_a_value_a_param_does_not_take_is_refused_with_a_did_you_mean(machine: Machine) -> None:
    body = "outcomes: [done]\nstates:\n  a: {do: send, with: {message: hi, keep: %s}, on: {sent: done}}\n"
    assert findings(machine("m", body % "lats")) == [
        "3:43 E332 param 'keep' of 'send' takes 'all' or 'last', not 'lats'; did you mean 'last'?"
    ]
    assert findings(machine("n", body % "3")) == ["3:43 E306 param 'keep' of 'send' takes str, not int 3"]
    for fine in ("last", "all", "'${params.k}'"):
        assert findings(machine("o", "params: {k: {type: str, default: last}}\n" + body % fine)) == []


def test_good_machine_has_no_findings(machine: Machine) -> None:
    assert findings(machine("m", GOOD)) == []


def test_all_findings_of_a_valid_schema_at_once(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          a: {do: wait, with: {secnds: 1}, on: {done: donne}}
          b: {do: wait, timer: 1, on: {done: done}}
    """,
    )
    assert findings(path) == [
        "3:24 E302 unknown param 'secnds' of 'wait'; did you mean 'seconds'?",
        "3:47 E301 unknown target 'donne': not a state or outcome; did you mean 'done'?",
        "4:3 W400 state 'b' cannot be reached from 'a'",
        "4:24 E310 the state has a timer, so 'on' must map 'timeout'",
    ]


def test_recursion_through_a_chain(machine: Machine) -> None:
    machine("ping", "outcomes: [done]\nstates:\n  a: {do: pong, on: {done: done}}\n")
    machine("pong", "outcomes: [done]\nstates:\n  a: {do: ping, on: {done: done}}\n")
    found = findings(machine("top", "outcomes: [done]\nstates:\n  a: {do: ping, on: {done: done}}\n"))
    assert any("E312 'ping' calls itself: ping -> pong -> ping" in f for f in found)


def test_machine_may_not_take_a_builtin_name_and_shadows_a_primitive(machine: Machine) -> None:
    machine("probe", "outcomes: [done]\nstates:\n  a: {do: log, with: {text: x}, on: {done: done}}\n")
    path = machine(
        "top", "outcomes: [done]\nstates:\n  a: {do: probe, with: {gain: 1}, on: {ok: done, failure: done}}\n"
    )
    assert codes(path.parent / "probe.yaml") == ["W406"]  # a user's machine shadows the primitive (docs/REFERENCE.md#hfsm-run)
    machine("wait", "outcomes: [done]\nstates:\n  a: {do: log, with: {text: x}, on: {done: done}}\n")
    assert "E319" in codes(path.parent / "wait.yaml")


@pytest.mark.parametrize(
    ("body", "code"),
    [
        (
            "outcomes: [done]\nstates:\n  a: {do: wait, on: {done: done}}\n  b: {do: wait, on: {done: done}}\n",
            "W400",
        ),
        ("outcomes: [done, never]\nstates:\n  a: {do: wait, on: {done: done}}\n", "W401"),
        (
            "outcomes: [done]\nstates:\n  a: {do: wait, on: {done: b}}\n  b: {do: wait, on: {done: a}}\n",
            "W402",
        ),
    ],
)
def test_warnings_become_errors_with_strict(machine: Machine, body: str, code: str) -> None:
    path = machine("m", body)
    assert code in codes(path)
    with pytest.raises(UserError) as info:
        load([path], strict=True)
    assert all(f.severity is Severity.ERROR for f in info.value.findings)


def test_loop_bounded_by_a_timer_above(machine: Machine) -> None:
    machine(
        "loop",
        """
        outcomes: [done]
        states:
          a: {do: wait, with: {seconds: 1}, on: {done: b}}
          b:
            choose:
              - {if: "true", then: a}
              - {else: done}
    """,
    )
    path = machine(
        "top", "outcomes: [done]\nstates:\n  a: {do: loop, timer: 5, on: {done: done, timeout: done}}\n"
    )
    assert codes(path) == []


def test_machine_timer_reaches_timeout(machine: Machine) -> None:
    path = machine("m", "outcomes: [done, timeout]\ntimer: 3\nstates:\n  a: {do: wait, on: {done: done}}\n")
    assert codes(path) == []
