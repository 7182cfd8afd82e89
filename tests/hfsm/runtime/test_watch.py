"""Watches, state.time and machine.time (docs/REFERENCE.md#watches), with exact ticks (dt 0.05)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from helpers import execute

Machine = Callable[[str, str], Path]


def events(records: list[dict[str, Any]]) -> list[tuple[float, str, str]]:
    return [(r["t"], r["path"][-1], r["event"]) for r in records if r["kind"] == "event"]


def test_a_watch_on_state_time_leaves_in_the_tick_it_first_holds(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          idle:
            do: wait
            watch:
              - if: "state.time >= 0.3"
                then: done
            on: {done: done}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("done", 0.3)
    assert events(records) == [(0.3, "idle", "state.time >= 0.3")]


def test_a_watch_wins_over_the_callee_end_but_not_over_timers_or_messages(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [watched, ended, timed_out]
        states:
          w:
            do: wait
            with: {seconds: 0.3}
            watch: [{if: "state.time >= 0.3", then: watched}]
            on: {done: ended}
    """,
    )
    assert execute(path)[0].agents["robot"].outcome == "watched"
    path = machine(
        "n",
        """
        outcomes: [watched, timed_out]
        states:
          w:
            do: wait
            timer: 0.3
            watch: [{if: "state.time >= 0.3", then: watched}]
            on: {done: watched, timeout: timed_out}
    """,
    )
    assert execute(path)[0].agents["robot"].outcome == "timed_out"
    path = machine(
        "o",
        """
        outcomes: [watched, heard]
        receives: [go]
        states:
          kick: {do: send, with: {message: go, to: all}, on: {sent: w}}
          w:
            do: wait
            watch: [{if: "state.time >= 0.05", then: watched}]
            on: {done: watched, go: heard}
    """,
    )
    assert execute(path)[0].agents["robot"].outcome == "heard"


def test_the_machine_watch_is_tried_first_and_reads_the_state_it_is_tried_in(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [by_machine, by_state, done]
        watch:
          - if: "state.time >= 0.2"
            then: by_machine
        states:
          first: {do: wait, with: {seconds: 0.15}, on: {done: second}}
          second:
            do: wait
            watch: [{if: "machine.time >= 0.2", then: by_state}]
            on: {done: done}
    """,
    )
    result, _ = execute(path)
    # machine.time reaches 0.2 at t=0.2 (state.time 0.05): the state's watch; the machine's needs t=0.35
    assert (result.agents["robot"].outcome, result.time) == ("by_state", 0.2)
    path = machine(
        "n",
        """
        outcomes: [by_machine, by_state, done]
        watch: [{if: "machine.time >= 0.2", then: by_machine}]
        states:
          only:
            do: wait
            watch: [{if: "state.time >= 0.2", then: by_state}]
            on: {done: done}
    """,
    )
    assert execute(path)[0].agents["robot"].outcome == "by_machine"


def test_on_entry_a_watch_acts_before_with_and_after_an_early_message(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {go: true}
        outcomes: [watched, done]
        states:
          w:
            do: wait
            with: {seconds: "${1 / 0}"}
            watch: [{if: vars.go, then: watched}]
            on: {done: done}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("watched", 0.0)
    assert [r for r in records if r["kind"] == "error"] == []
    path = machine(
        "n",
        """
        outcomes: [watched, heard]
        receives: [go]
        states:
          kick: {do: send, with: {message: go, to: all}, on: {sent: pause}}
          pause: {do: wait, with: {seconds: 0.1}, on: {done: w}}
          w:
            do: wait
            watch: [{if: true, then: watched}]
            on: {done: watched, go: heard}
    """,
    )
    assert execute(path)[0].agents["robot"].outcome == "heard"


def test_a_watch_to_its_own_state_is_passed_over_and_later_watches_are_tried(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {alarm: false}
        outcomes: [done, gave_up]
        watch:
          - if: "vars.alarm"
            then: dock
        states:
          w:
            do: set
            with: {alarm: true}
            on: {done: dock}
          dock:
            do: wait
            watch:
              - if: "state.time >= 0.2"
                then: gave_up
            on: {done: done}
    """,
    )
    result, records = execute(path, max_time=5)
    # the machine's watch into `dock` holds all along: passed over (docs/REFERENCE.md#watches), never restarting
    # `dock`, and `dock`'s own watch is still tried
    assert (result.agents["robot"].outcome, result.agents["robot"].time) == ("gave_up", 0.2)
    assert [r["t"] for r in records if r["kind"] == "enter" and r["path"][-1] == "dock"] == [0.0]


def test_a_watch_that_fails_to_evaluate_is_an_error(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {l: []}
        outcomes: [done, broken]
        states:
          w:
            do: wait
            with: {seconds: 1}
            watch: [{if: "state.time > 0.1 and vars.l[0]", then: done}]
            on: {done: done, error: broken}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("broken", 0.15)
    assert next(r["message"] for r in records if r["kind"] == "error").startswith("watch 'state.time > 0.1")


def test_a_watch_on_vars_alone_lets_a_static_world_skip_idle_ticks(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {go: false}
        outcomes: [done]
        states:
          w:
            do: wait
            watch: [{if: vars.go, then: done}]
            on: {done: done}
    """,
    )
    result, _ = execute(path)
    assert result.error == "blocked forever: robot in m/w"


def test_time_since_entry_is_rounded(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {t: 0}
        outcomes: [done]
        outputs: {t: "${vars.t}"}
        states:
          w:
            do: wait
            watch: [{if: "state.time == 0.3", then: keep}]
            on: {done: done}
          keep: {do: set, with: {t: "${machine.time}"}, on: {done: done}}
    """,
    )
    assert execute(path)[0].agents["robot"].outputs == {"t": 0.3}


def test_a_yaml_literal_is_a_condition(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [a, b, c, d, e]
        states:
          pick:
            choose:
              - if: false
                then: a
              - if: null
                then: b
              - if: 0
                then: c
              - if: 2.5
                then: d
              - else: e
    """,
    )
    result, records = execute(path)
    assert result.agents["robot"].outcome == "d"
    assert events(records) == [(0.0, "pick", "2.5")]
