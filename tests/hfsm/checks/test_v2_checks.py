"""Checks of watches, retries, live names and inputs (docs/REFERENCE.md#watches and #retries), and the warnings of language v2."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from hfsm.checks.forgotten import reads_like_expression
from hfsm.errors import UserError
from hfsm.load import load
from hfsm.registry import Registry
from hfsm.world import InputSpec

Machine = Callable[[str, str], Path]
BATTERY = {"none": {"battery": InputSpec("battery", "float", "charge, 0 to 1")}}


def found(path: Path, worlds: dict[str, dict[str, InputSpec]] | None = None) -> list[str]:
    try:
        result = load([path], registry=Registry(), world_inputs=worlds).warnings
    except UserError as err:
        result = err.findings
    return [f"{Path(f.file).stem}:{f.line}:{f.col} {f.code} {f.message}" for f in result]


STATE_NAMES = "only in a state's with, timer and watch, the machine's watch, and a choice's if"


def test_retry_outcomes_and_counts(machine: Machine) -> None:
    path = machine(
        "r",
        """
        outcomes: [done]
        params: {n: {type: int, default: 2}}
        vars: {x: 0}
        states:
          go:
            do: wait
            with: {seconds: 1}
            retry: {on: [done, blocked, timeout, error], times: "${vars.x}", delay: "${state.time}"}
            on: {}
          next:
            do: wait
            retry: {on: [done], times: "${params.n}", delay: "${params.n / 2}"}
            on: {done: done}
        """,
    )
    assert found(path) == [
        "r:8:18 E328 retried outcome 'done' must still be mapped in 'on' (taken after the last retry)",
        "r:8:24 E327 'wait' has no outcome 'blocked' to retry (it has: done, and 'error')",
        "r:8:33 E327 'wait' has no outcome 'timeout' to retry (it has: done, and 'error'); "
        "a state's own timer is never retried",
        "r:8:60 E314 'vars.x': only params and agent.id may be read here",
        f"r:8:80 E331 'state.time' cannot be read in a retry's 'times' or 'delay'; {STATE_NAMES}",
        "r:10:3 W400 state 'next' cannot be reached from 'go'",
    ]


def test_live_names_where_they_may_be_read_and_a_literal_if(machine: Machine) -> None:
    path = machine(
        "e",
        """
        outcomes: [done]
        params: {t: {type: float, default: 1}}
        vars: {x: 0}
        timer: "${params.t + machine.time + state.time + in.battery}"
        outputs: {a: "${state.attempt}", b: "${machine.time}", c: "${in.battery}", d: "${in.batery}"}
        watch:
          - {if: "state.time > 3 and machine.time > 1", then: done}
          - {if: "vars.y", then: nowhere}
        states:
          a:
            do: wait
            with: {seconds: "${state.attempt + in.battery}"}
            timer: "${state.time + 1}"
            watch:
              - {if: "state.tme > 1", then: b}
            on: {done: b, timeout: done}
          b:
            choose:
              - {if: true, then: c}
              - {else: done}
          c:
            choose:
              - {if: 3, then: done}
              - {else: done}
        """,
    )
    assert found(path, BATTERY) == [
        "e:4:22 E331 'machine.time' cannot be read in the machine's timer",
        f"e:4:37 E331 'state.time' cannot be read in the machine's timer; {STATE_NAMES}",
        "e:4:50 E331 'in.battery' cannot be read in the machine's timer; only params and agent.id",
        f"e:5:17 E331 'state.attempt' cannot be read in the machine's outputs; {STATE_NAMES}",
        "e:5:82 E330 the run's world declares no input 'in.batery' (it declares: battery); "
        "did you mean 'battery'?",
        "e:8:11 E314 unknown variable 'y'",
        "e:8:26 E301 unknown target 'nowhere': not a state or outcome",
        "e:15:15 E314 unknown name 'state.tme'; did you mean 'state.time'?",
    ]


def test_world_none_declares_no_input(machine: Machine) -> None:
    path = machine(
        "i", 'outcomes: [done]\nstates:\n  a: {do: log, with: {text: "${in.battery}"}, on: {done: done}}\n'
    )
    assert found(path, {"none": {}}) == [
        "i:3:32 E330 the run's world declares no input 'in.battery' (it declares: none)"
    ]
    assert found(path) == []  # no world told: inputs are not checked


def test_watches_and_timers_end_loops(machine: Machine) -> None:
    loop = "outcomes: [done]\n{}states:\n  a: {{do: wait, with: {{seconds: 1}}, on: {{done: b}}}}\n" + (
        "  b: {{do: wait, with: {{seconds: 1}}, {}on: {{done: a{}}}}}\n"
    )
    bare = machine("bare", loop.format("", "", ""))
    assert found(bare) == [
        "bare:1:12 W401 outcome 'done' is never reached",
        "bare:3:3 W402 states a -> b can loop forever: no timer on 'bare' or above it",
    ]
    watched = machine(
        "watched", loop.format("vars: {n: 0}\nwatch:\n  - {if: 'vars.n > 3', then: done}\n", "", "")
    )
    assert found(watched) == []
    timed = machine("timed", loop.format("", "timer: 9, ", ", timeout: done"))
    assert found(timed) == []
    back = machine("back", loop.format("", "timer: 9, ", ", timeout: a"))  # the timer leads back in
    assert [f.split()[1] for f in found(back)] == ["W401", "W402"]


def test_join_rules_and_watches_are_arcs(machine: Machine) -> None:
    path = machine(
        "arcs",
        """
        outcomes: [done, stopped]
        states:
          both:
            parallel:
              a: {do: wait, with: {seconds: 1}}
            join:
              - {when: {a: done}, then: next}
          next:
            do: wait
            with: {seconds: 1}
            watch:
              - {if: "state.time > 0.5", then: last}
            on: {done: done}
          last: {do: wait, with: {seconds: 1}, on: {done: stopped}}
        """,
    )
    assert found(path) == []


def test_regions_that_can_wait_forever_or_share_a_message(machine: Machine) -> None:
    machine(
        "inner", "outcomes: [done]\nreceives: [go]\nstates:\n  y: {do: wait, on: {done: done, go: done}}\n"
    )
    machine("helper", "outcomes: [done]\nstates:\n  x: {do: inner, on: {done: done}}\n")
    body = """
        outcomes: [done]
        receives: [go]
        {}states:
          both:
            parallel:
              a: {{do: wait_for, with: {{message: go}}}}
              b: {{do: helper}}
              c: {{do: wait, with: {{seconds: 1}}, background: true}}
            join:
              - {{when: {{a: received, b: done}}, then: done}}
        """
    path = machine("top", body.format(""))
    assert found(path) == [
        "top:6:7 W403 region 'a' can wait forever ('wait_for' of message 'go') and nothing above it has a "
        "timer; put a timer on 'both'",
        "top:7:7 W403 region 'b' can wait forever (helper/x/inner/y: 'wait' without seconds) and nothing "
        "above it has a timer; put a timer on 'both'",
        "top:7:7 W404 regions 'a' and 'b' both consume message 'go': 'a' takes it first and 'b' may never see it",
    ]
    timed = machine(
        "timed", body.format("watch:\n          - {if: 'machine.time > 60', then: done}\n        ")
    )
    assert [f.split()[1] for f in found(timed)] == ["W404"]


def test_a_forgotten_wrap(machine: Machine) -> None:
    path = machine(
        "f",
        """
        outcomes: [done]
        vars: {lap: 0, name: x}
        outputs: {lap: vars.lap}
        states:
          a: {do: set, with: {lap: "vars.lap + 1", name: "params.x"}, on: {done: b}}
          b: {do: log, with: {text: "vars.lap"}, on: {done: c}}
          c: {do: wait, with: {seconds: "vars.lap * 2"}, on: {done: d}}
          d: {do: send, with: {message: go, data: {n: vars.lap, m: [agent.id], t: "lap ${vars.lap}"}}, on: {sent: done}}
        """,
    )
    assert found(path) == [
        "f:3:16 W405 'vars.lap' reads like an expression but is taken as text; write '${vars.lap}'",
        "f:5:28 W405 var 'lap' starts as int, but this sets it to the text 'vars.lap + 1'; write '${vars.lap + 1}'",
        "f:5:50 W405 'params.x' reads like an expression but is taken as text; write '${params.x}'",
        "f:6:29 W405 'vars.lap' reads like an expression but is taken as text; write '${vars.lap}'",
        "f:7:33 E306 param 'seconds' of 'wait' takes float, not str 'vars.lap * 2'; write '${vars.lap * 2}' "
        "for an expression",
        "f:8:47 W405 'vars.lap' reads like an expression but is taken as text; write '${vars.lap}'",
        "f:8:61 W405 'agent.id' reads like an expression but is taken as text; write '${agent.id}'",
    ]


def test_prose_is_not_taken_for_a_forgotten_wrap() -> None:
    assert reads_like_expression("vars.lap + 1") and reads_like_expression("in.battery < 0.2")
    for text in ("vars.n is big", "found vars.n corners", "lap ${vars.lap}", "go", "3.5"):
        assert not reads_like_expression(text), text
