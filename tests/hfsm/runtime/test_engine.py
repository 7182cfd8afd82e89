"""Interpreter semantics, docs/REFERENCE.md#states to 6."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from helpers import execute

from hfsm.primitive import Cancelled, Context, Outcome, primitive
from hfsm.registry import Registry
from hfsm.world import NullWorld

Machine = Callable[[str, str], Path]


def kinds(records: list[dict[str, Any]], kind: str) -> list[dict[str, Any]]:
    return [r for r in records if r["kind"] == kind]


def test_wait_ends_in_the_tick_its_span_ends(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          a: {do: wait, with: {seconds: 0.12}, on: {done: b}}
          b: {do: wait, with: {seconds: 1.0}, on: {done: done}}
    """,
    )
    result, _ = execute(path)
    assert result.agents["robot"].outcome == "done"
    assert result.agents["robot"].time == 0.15 + 1.0


def test_zero_time_chain_and_outputs(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {n: 1}
        outcomes: [done]
        outputs: {twice: "${vars.n * 2}", text: "n=${vars.n}"}
        states:
          a: {do: set, with: {n: "${vars.n + 2}"}, on: {done: b}}
          b: {do: wait, with: {seconds: 0}, on: {done: done}}
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outputs, result.time) == ({"twice": 6, "text": "n=3"}, 0.0)


def test_machine_timer_cancels_at_any_depth_and_wins_ties(machine: Machine) -> None:
    machine(
        "inner",
        """
        outcomes: [done]
        states:
          w: {do: wait, with: {seconds: 1.0}, on: {done: done}}
    """,
    )
    path = machine(
        "outer",
        """
        vars: {reached: false}
        outcomes: [done, timeout]
        outputs: {reached: "${vars.reached}"}
        timer: 1.0
        states:
          call: {do: inner, timer: 1.0, on: {done: mark, timeout: done}}
          mark: {do: set, with: {reached: true}, on: {done: done}}
    """,
    )
    result, records = execute(path)
    assert result.agents["robot"].outcome == "timeout"
    assert result.agents["robot"].outputs == {"reached": False}
    assert [r["timer"] for r in kinds(records, "timeout")] == ["machine"]
    assert result.time == 1.0


def test_state_timer_takes_the_timeout_arc(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [slow, fast]
        states:
          a: {do: wait, timer: 0.5, on: {done: fast, timeout: slow}}
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("slow", 0.5)


def test_timer_expression_and_callee_timeout_outcome_share_the_arc(machine: Machine) -> None:
    machine(
        "child",
        """
        params: {limit: {type: float}}
        outcomes: [done]
        timer: "${params.limit}"
        states:
          w: {do: wait, on: {done: done}}
    """,
    )
    path = machine(
        "m",
        """
        outcomes: [ok, late]
        states:
          a: {do: child, with: {limit: 0.3}, timer: 5, on: {done: ok, timeout: late}}
    """,
    )
    result, _ = execute(path)
    assert (result.agents["robot"].outcome, result.time) == ("late", 0.3)


def test_bad_timer_value_is_an_error_event(machine: Machine) -> None:
    path = machine(
        "m",
        """
        params: {t: {type: float, default: -1}}
        outcomes: [done, failure]
        states:
          a: {do: wait, timer: "${params.t}", on: {done: done, timeout: done, error: failure}}
    """,
    )
    result, records = execute(path)
    assert result.agents["robot"].outcome == "failure"
    assert "positive number" in kinds(records, "error")[0]["message"]


PING = """
    receives: [ping]
    outcomes: [got, done]
    states:
      start:
        choose:
          - if: "agent.id == 'a'"
            then: send
          - else: listen
      send: {do: send, with: {message: ping, data: {n: 1}}, on: {sent: idle}}
      idle: {do: wait, with: {seconds: 1}, on: {done: done}}
      listen: {do: wait, with: {seconds: 5}, on: {done: done, ping: got}}
"""


def test_message_arrives_next_tick_and_preempts_the_callee(machine: Machine) -> None:
    result, records = execute(machine("m", PING), agents=["a", "b"])
    assert result.agents["b"].outcome == "got"
    assert result.agents["b"].time == 0.05
    (send,) = kinds(records, "send")
    (receive,) = kinds(records, "receive")
    assert (receive["agent"], receive["t"], receive["sender"], receive["id"]) == ("b", 0.05, "a", send["id"])
    assert send["data"] == {"n": 1} and "data" not in receive


def test_early_message_takes_the_arc_at_entry_without_evaluating_with(machine: Machine) -> None:
    path = machine(
        "m",
        """
        receives: [go]
        outcomes: [done, failure]
        states:
          start:
            choose:
              - if: "agent.id == 'a'"
                then: send
              - else: nap
          send: {do: send, with: {message: go}, on: {sent: done}}
          nap: {do: wait, with: {seconds: 1}, on: {done: listen}}
          listen: {do: wait, with: {seconds: "${1 / 0}"}, on: {done: failure, go: done, error: failure}}
    """,
    )
    result, records = execute(path, agents=["a", "b"])
    assert result.agents["b"].outcome == "done"
    assert not kinds(records, "error")


def test_wait_for_outputs_and_save(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {n: 0, who: ""}
        outcomes: [done]
        outputs: {n: "${vars.n}", who: "${vars.who}"}
        states:
          start:
            choose:
              - if: "agent.id == 'a'"
                then: send
              - else: receive
          send: {do: send, with: {message: hi, to: b, data: {n: 42}}, on: {sent: done}}
          receive: {do: wait_for, with: {message: hi}, save: {n: n, who: sender}, on: {received: done}}
    """,
    )
    result, _ = execute(path, agents=["a", "b"])
    assert result.agents["b"].outputs == {"n": 42, "who": "a"}


def test_message_arc_wins_over_wait_for_of_the_same_message(machine: Machine) -> None:
    path = machine(
        "m",
        """
        receives: [hi]
        outcomes: [arc, consumed]
        states:
          start:
            choose:
              - if: "agent.id == 'a'"
                then: send
              - else: receive
          send: {do: send, with: {message: hi}, on: {sent: arc}}
          receive: {do: wait_for, with: {message: hi}, on: {received: consumed, hi: arc}}
    """,
    )
    result, _ = execute(path, agents=["a", "b"])
    assert result.agents["b"].outcome == "arc"


def test_unmapped_error_passes_up_and_ends_the_run(machine: Machine) -> None:
    machine(
        "child",
        """
        outcomes: [done]
        states:
          bad: {do: wait, with: {seconds: "${1 / 0}"}, on: {done: done}}
    """,
    )
    path = machine(
        "top",
        """
        outcomes: [done]
        states:
          call: {do: child, on: {done: done}}
    """,
    )
    result, _records = execute(path)
    assert result.exit_code == 1
    assert result.error is not None and result.error.startswith("top/call/bad: division by zero")
    assert result.agents["robot"].outcome is None


def test_mapped_error_and_any_error(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done, failure]
        any: {error: failure}
        states:
          first: {do: wait, with: {seconds: "${1 / 0}"}, on: {done: done}}
    """,
    )
    result, _ = execute(path)
    assert result.agents["robot"].outcome == "failure"


def test_send_to_unknown_agent_is_an_error(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          s: {do: send, with: {message: hi, to: nobody}, on: {sent: done}}
    """,
    )
    result, _ = execute(path)
    assert result.error is not None and "no agent named 'nobody'" in result.error


def test_blocked_forever(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          s: {do: wait_for, with: {message: never}, on: {received: done}}
    """,
    )
    result, records = execute(path)
    assert result.error == "blocked forever: robot in m/s"
    assert kinds(records, "exit")[-1] == {
        "t": 0.0,
        "agent": "robot",
        "path": ["m"],
        "kind": "exit",
        "outcome": None,
    }


def test_max_time_stops_the_run(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          s: {do: wait, with: {seconds: 100}, on: {done: done}}
    """,
    )
    result, _ = execute(path, max_time=2)
    assert result.error is not None and "max-time" in result.error and result.time == 2.0


def test_more_than_1000_entries_in_a_tick_is_fatal(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {n: 0}
        outcomes: [done]
        timer: 10
        states:
          a: {do: set, with: {n: "${vars.n + 1}"}, on: {done: a}}
    """,
    )
    result, _ = execute(path)
    assert result.error is not None and "more than 1000 state entries" in result.error


def test_vars_are_fresh_on_every_call(machine: Machine) -> None:
    machine(
        "child",
        """
        vars: {items: []}
        outcomes: [done]
        outputs: {items: "${vars.items}"}
        states:
          add: {do: set, with: {items: "${vars.items + [1]}"}, on: {done: done}}
    """,
    )
    path = machine(
        "m",
        """
        vars: {first: [], second: []}
        outcomes: [done]
        outputs: {second: "${vars.second}"}
        states:
          one: {do: child, save: {first: items}, on: {done: two}}
          two: {do: child, save: {second: items}, on: {done: done}}
    """,
    )
    result, _ = execute(path)
    assert result.agents["robot"].outputs == {"second": [1]}


def test_param_type_checked_at_run_time(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {s: "x"}
        outcomes: [done, failure]
        states:
          w: {do: wait, with: {seconds: "${vars.s}"}, on: {done: done, error: failure}}
    """,
    )
    _, records = execute(path)
    assert "takes float" in kinds(records, "error")[0]["message"]


@primitive(outcomes=["arrived", "blocked"], failures=["blocked"], outputs=["distance"])
def walk(ctx: Context, *, distance: float, speed: float = 0.5) -> str | Outcome:
    """Walk a distance; stops the robot when cancelled."""
    robot = ctx.robot
    robot["walking"] = True
    try:
        ctx.wait(distance / speed)
    except Cancelled:
        robot["cancelled_at"] = ctx.time
        raise
    finally:
        robot["walking"] = False
    return Outcome("arrived", distance=distance)


@primitive(outcomes=["done"])
def explode(ctx: Context) -> str:
    ctx.wait()
    raise RuntimeError("boom")


class RobotWorld(NullWorld):
    """`--world none` whose agents' handles are dicts, to watch primitives clean up."""

    def __init__(self) -> None:
        super().__init__()
        self.robots: dict[str, dict[str, Any]] = {}

    def start(self, agents: Sequence[str], dt: float) -> None:
        self.robots = {a: {} for a in agents}

    def handle(self, agent: str) -> dict[str, Any]:
        return self.robots[agent]


def test_primitive_blocks_returns_outputs_and_is_cancelled_with_cleanup(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {d: 0}
        outcomes: [done, timeout]
        outputs: {d: "${vars.d}"}
        timer: 3
        states:
          short: {do: walk, with: {distance: 1.0}, save: {d: distance}, on: {arrived: long, blocked: done}}
          long: {do: walk, with: {distance: 10.0}, on: {arrived: done, blocked: done}}
    """,
    )
    world = RobotWorld()
    result, _ = execute(path, registry=Registry([walk]), world=world)
    assert result.agents["robot"].outcome == "timeout"
    assert result.agents["robot"].outputs == {"d": 1.0}
    assert world.robots["robot"] == {"walking": False, "cancelled_at": 3.0}


def test_primitive_exception_is_an_error_naming_the_path(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          kaboom: {do: explode, on: {done: done}}
    """,
    )
    result, _ = execute(path, registry=Registry([explode]), world=RobotWorld())
    assert result.error == "m/kaboom: RuntimeError: boom"
    assert "Traceback" in result.traceback


def test_same_seed_same_trace(machine: Machine) -> None:
    path = Path(__file__).resolve().parents[3] / "examples" / "ping_pong.yaml"
    first = execute(path, agents=["a", "b"])[1]
    assert first == execute(path, agents=["a", "b"])[1]
