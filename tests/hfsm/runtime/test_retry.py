"""Retries (docs/REFERENCE.md#retries) and cancels that cannot be refused, with exact ticks (dt 0.05)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from helpers import execute

from hfsm.primitive import Cancelled, Context, primitive
from hfsm.registry import Registry

Machine = Callable[[str, str], Path]

NAVIGATE = """
    params:
      waypoint: {{type: str}}
      attempt: {{type: int}}
      succeed_at: {{type: int, default: {succeed_at}}}
    outcomes: [arrived, unreachable]
    outputs: {{tried: "${{params.attempt}}"}}
    states:
      drive: {{do: wait, with: {{seconds: 1.0}}, on: {{done: pick}}}}
      pick:
        choose:
          - if: "params.attempt >= params.succeed_at"
            then: arrived
          - else: unreachable
"""

SPEC_EXAMPLE = """
    params:
      target: {{type: str, default: dock}}
    outcomes: [done, give_up]
    states:
      navigate:
        do: navigate_to_waypoint
        with: {{waypoint: "${{params.target}}", attempt: "${{state.attempt}}"}}
        retry: {{on: [unreachable, error], times: 3, delay: 1.5}}
        timer: {timer}                                   # covers every attempt
        on: {{arrived: done, unreachable: give_up, timeout: give_up}}
"""


def example(machine: Machine, succeed_at: int = 3, timer: float = 120) -> Path:
    """docs/REFERENCE.md#retries's example as written, around a stand-in that arrives on attempt `succeed_at`."""
    machine("navigate_to_waypoint", NAVIGATE.format(succeed_at=succeed_at))
    return machine("top", SPEC_EXAMPLE.format(timer=timer))


def of_kind(records: list[dict[str, Any]], kind: str) -> list[dict[str, Any]]:
    return [r for r in records if r["kind"] == kind]


def test_spec_example_retries_after_the_delay_with_with_evaluated_anew(machine: Machine) -> None:
    result, records = execute(example(machine))
    robot = result.agents["robot"]
    # attempts at 0, 2.5 and 5.0, each a second long; the third arrives
    assert (robot.outcome, robot.time) == ("done", 6.0)
    calls = [r for r in of_kind(records, "enter") if r["path"] == ["top", "navigate", "drive"]]
    assert [r["t"] for r in calls] == [0.0, 2.5, 5.0]
    retries = [
        (r["t"], r["attempt"], r["outcome"]) for r in of_kind(records, "event") if r["event"] == "retry"
    ]
    assert retries == [(1.0, 2, "unreachable"), (3.5, 3, "unreachable")]
    assert [r["t"] for r in of_kind(records, "enter") if r["path"] == ["top", "navigate"]] == [0.0]


def test_after_the_last_retry_the_arc_is_taken(machine: Machine) -> None:
    result, records = execute(example(machine, succeed_at=9))
    robot = result.agents["robot"]
    # four calls (the first and three retries), the last ending at 3 * (1 + 1.5) + 1 = 8.5
    assert (robot.outcome, robot.time) == ("give_up", 8.5)
    assert [r["attempt"] for r in of_kind(records, "event") if r["event"] == "retry"] == [2, 3, 4]


def test_save_is_applied_at_every_end_so_with_reads_the_last(machine: Machine) -> None:
    machine("navigate_to_waypoint", NAVIGATE.format(succeed_at=3))
    path = machine(
        "top",
        """
        vars: {tried: 0}
        outcomes: [done, give_up]
        outputs: {tried: "${vars.tried}"}
        states:
          nav:
            do: navigate_to_waypoint
            with: {waypoint: "after ${vars.tried}", attempt: "${vars.tried + 1}"}
            save: {tried: tried}
            retry: {on: [unreachable], times: 5}
            on: {arrived: done, unreachable: give_up}
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outcome, result.agents["robot"].outputs, result.time) == (
        "done",
        {"tried": 3},
        3.0,
    )


def test_the_timer_covers_every_attempt_and_ends_a_delay(machine: Machine) -> None:
    result, _ = execute(example(machine, timer=2))
    assert (result.agents["robot"].outcome, result.time) == ("give_up", 2.0)


def test_retrying_error_covers_the_with_of_the_call(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done, broken]
        states:
          w:
            do: wait
            with: {seconds: "${1 / (state.attempt - 1)}"}
            retry: {on: [error], times: 1}
            on: {done: done, error: broken}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("done", 1.0)
    assert [r["attempt"] for r in of_kind(records, "event") if r["event"] == "retry"] == [2]
    assert len(of_kind(records, "error")) == 1


def test_retrying_error_does_not_cover_watches(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {l: []}
        outcomes: [done, broken]
        states:
          w:
            do: wait
            with: {seconds: 1}
            watch: [{if: "vars.l[0]", then: done}]
            retry: {on: [error], times: 5}
            on: {done: done, error: broken}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("broken", 0.0)
    assert [r for r in of_kind(records, "event") if r["event"] == "retry"] == []


def test_a_message_ends_the_state_during_a_delay(machine: Machine) -> None:
    path = machine(
        "top",
        """
        outcomes: [done, stopped]
        receives: [stop]
        states:
          kick: {do: send, with: {message: stop, to: all}, on: {sent: nav}}
          nav:
            do: wait
            with: {seconds: 0}
            retry: {on: [done], times: 3, delay: 1.5}
            on: {done: done, stop: stopped}
    """,
    )
    result, records = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("stopped", 0.05)
    assert [(r["t"], r["attempt"]) for r in of_kind(records, "event") if r["event"] == "retry"] == [(0.0, 2)]


def test_zero_delay_retries_in_the_same_tick_and_times_from_params(machine: Machine) -> None:
    path = machine(
        "m",
        """
        params:
          times: {type: int, default: 4}
        vars: {n: 0}
        outcomes: [done]
        outputs: {n: "${vars.n}"}
        states:
          count:
            do: set
            with: {n: "${vars.n + 1}"}
            retry: {on: [done], times: "${params.times}"}
            on: {done: done}
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outputs, result.time) == ({"n": 5}, 0.0)


@primitive(outcomes=["done"])
def stubborn(ctx: Context, *, returns: bool = False) -> str:
    """Catches its cancel and waits on, or returns: both are errors."""
    while True:
        try:
            ctx.wait(1.0)
        except Cancelled:
            if returns:
                return "done"


def test_a_primitive_that_swallows_its_cancel_is_an_error(machine: Machine) -> None:
    for returns in ("false", "true"):
        path = machine(
            f"m{returns}",
            f"""
            outcomes: [done, timeout, broken]
            states:
              s: {{do: stubborn, with: {{returns: {returns}}}, timer: 0.2, on: {{done: done, timeout: timeout, error: broken}}}}
        """,
        )
        result, records = execute(path, registry=Registry([stubborn]))
        assert (result.agents["robot"].outcome, result.time) == ("broken", 0.2)
        message = of_kind(records, "error")[0]["message"]
        assert message.startswith("primitive 'stubborn' swallowed its cancellation")
