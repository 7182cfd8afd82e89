"""Agents that fail, docs/REFERENCE.md#agents-that-fail: cancelled with clean-up, silent, deaf, one `failed` record."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from helpers import execute

from hfsm.primitive import Cancelled, Context, primitive
from hfsm.registry import Registry
from hfsm.runtime.failing import Failure
from hfsm.world import NullWorld

Machine = Callable[[str, str], Path]

PING = """
    outcomes: [done]
    receives: [ping]
    states:
      start:
        choose:
          - {if: "agent.id == 'a'", then: later}
          - {else: listen}
      later: {do: wait, with: {seconds: 0.5}, on: {done: ping}}
      ping: {do: send, with: {message: ping, to: b}, on: {sent: done}}
      listen: {do: wait_for, with: {message: ping}, on: {received: done}}
"""


def test_messages_to_a_failed_agent_are_lost(machine: Machine) -> None:
    result, records = execute(machine("m", PING), agents=["a", "b"], failures=[Failure("b", 0.2)])
    assert result.error is None
    assert {n: (r.outcome, r.time, r.failed) for n, r in result.agents.items()} == {
        "a": ("done", 0.5, None),
        "b": (None, 0.2, "--fail"),
    }
    mine = [(r["t"], r["kind"], r["path"]) for r in records if r["agent"] == "b" and r["t"] > 0]
    assert mine == [
        (0.2, "failed", ["m", "listen"]),
        (0.2, "exit", ["m", "listen"]),
        (0.2, "exit", ["m"]),
    ]
    assert [r for r in records if r["kind"] == "send"], "a still sends: sending to a failed agent is no error"


def test_a_failed_agent_sends_nothing_and_its_mailbox_is_gone(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        receives: [ping]
        states:
          start:
            choose:
              - {if: "agent.id == 'b'", then: listen}
              - {else: wait}
          wait: {do: wait, with: {seconds: 1}, on: {done: ping}}
          ping: {do: send, with: {message: ping}, on: {sent: done}}
          listen: {do: wait_for, with: {message: ping}, on: {received: done}}
        """,
    )
    result, records = execute(path, agents=["a", "b"], failures=[Failure("a", 0.5)])
    assert result.error == "blocked forever: b in m/listen"
    assert not [r for r in records if r["kind"] in ("send", "receive")]


def test_clean_up_runs_when_an_agent_fails(machine: Machine) -> None:
    cleaned: list[float] = []

    @primitive(outcomes=["done"])
    def walk(ctx: Context) -> str:
        try:
            ctx.wait(10)
        except Cancelled:
            cleaned.append(ctx.time)
            raise
        return "done"

    path = machine("m", "outcomes: [done]\nstates:\n  w: {do: walk, on: {done: done}}\n")
    result, records = execute(path, registry=Registry([walk]), failures=[Failure("robot", 1.0)])
    assert cleaned == [1.0]
    assert result.error == "every agent failed"
    assert [r["kind"] for r in records][-3:] == ["failed", "exit", "exit"]
    assert records[-2]["event"] == "failed"


def test_an_agent_failed_in_tick_0_never_starts(machine: Machine) -> None:
    result, records = execute(machine("m", PING), agents=["a", "b"], failures=[Failure("b", 0)])
    assert result.agents["b"].time == 0.0
    assert [r for r in records if r["agent"] == "b"] == [
        {"t": 0.0, "agent": "b", "path": ["m"], "kind": "failed", "reason": "--fail"}
    ]


def test_failures_fall_in_the_tick_their_span_ends(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 1}, on: {done: done}}\n")
    result, _ = execute(path, failures=[Failure("robot", 0.12)])
    assert (result.agents["robot"].time, result.error) == (0.15, "every agent failed")


def test_a_failed_agent_counts_as_ended_for_max_time(machine: Machine) -> None:
    path = machine(
        "m",
        """
        outcomes: [done]
        states:
          w: {do: wait, with: {seconds: "${1 if agent.id == 'a' else 100}"}, on: {done: done}}
        """,
    )
    result, _ = execute(path, agents=["a", "b"], failures=[Failure("b", 2)], max_time=10)
    assert result.error is None
    assert {n: (r.outcome, r.time) for n, r in result.agents.items()} == {"a": ("done", 1.0), "b": (None, 2.0)}


class FallingWorld(NullWorld):
    """A world that fails robot `b` at tick 4, as a simulator does when a battery dies."""

    static = False  # a world that fails agents on its own runs every tick

    def failures(self, tick: int) -> Sequence[tuple[str, str]]:
        return [("b", "battery empty")] if tick == 4 else []


def test_a_world_fails_an_agent(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 1}, on: {done: done}}\n")
    result, records = execute(path, agents=["a", "b"], world=FallingWorld(), failures=[])
    assert (result.agents["b"].failed, result.agents["b"].time) == ("battery empty", 0.2)
    assert result.agents["a"].outcome == "done"
    assert [r["reason"] for r in records if r["kind"] == "failed"] == ["battery empty"]


def test_blocked_forever_does_not_wait_for_a_failure_to_come(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  w: {do: wait, on: {done: done}}\n")
    result, _ = execute(path, agents=["a", "b"], failures=[Failure("b", 5)])
    assert (result.error, result.time) == ("blocked forever: a in m/w; b in m/w", 0.0)
    assert result.agents["b"].failed is None


def test_a_failure_between_two_timed_events_happens_in_its_tick(machine: Machine) -> None:
    path = machine("m", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 10}, on: {done: done}}\n")
    result, _ = execute(path, agents=["a", "b"], failures=[Failure("b", 5)])
    assert {n: (r.outcome, r.time, r.failed) for n, r in result.agents.items()} == {
        "a": ("done", 10.0, None),
        "b": (None, 5.0, "--fail"),
    }
