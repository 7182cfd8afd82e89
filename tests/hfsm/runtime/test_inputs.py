"""The world seam for inputs (docs/REFERENCE.md#watches): read when an expression asks, at most once a tick per agent."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from helpers import execute

from hfsm.world import InputSpec, NullWorld

Machine = Callable[[str, str], Path]


class CountingWorld(NullWorld):
    """Declares `tick` (the tick asked for) and `agent`; counts every read."""

    def __init__(self) -> None:
        super().__init__()
        self.reads: list[tuple[str, str, int]] = []

    def inputs(self) -> Mapping[str, InputSpec]:
        return {
            "tick": InputSpec("tick", "int", "the tick, as the world saw it"),
            "broken": InputSpec("broken", "float", "a sensor that fails"),
        }

    def read_input(self, agent: str, name: str, tick: int) -> Any:
        self.reads.append((agent, name, tick))
        if name == "broken":
            raise OSError("camera unplugged")
        return tick


def test_inputs_are_read_once_a_tick_and_only_when_asked(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {a: 0, b: 0}
        outcomes: [done]
        outputs: {a: "${vars.a}", b: "${vars.b}"}
        states:
          idle: {do: wait, with: {seconds: 0.1}, on: {done: look}}
          look: {do: set, with: {a: "${in.tick}", b: "${in.tick + in.tick}"}, on: {done: done}}
    """,
    )
    world = CountingWorld()
    result, _ = execute(path, agents=["r1", "r2"], world=world)
    assert result.agents["r1"].outputs == {"a": 2, "b": 4}
    assert world.reads == [("r1", "tick", 2), ("r2", "tick", 2)]


def test_a_machine_that_reads_no_input_costs_nothing(machine: Machine) -> None:
    path = machine(
        "m", "outcomes: [done]\nstates:\n  w: {do: wait, with: {seconds: 0.2}, on: {done: done}}\n"
    )
    world = CountingWorld()
    execute(path, world=world)
    assert world.reads == []


def test_an_undeclared_or_failing_input_is_an_error(machine: Machine) -> None:
    path = machine(
        "m", 'outcomes: [done]\nstates:\n  s: {do: log, with: {text: "${in.nope}"}, on: {done: done}}\n'
    )
    result, _ = execute(path)
    assert result.error == "m/s: world 'none' declares no input 'in.nope'"
    path = machine(
        "n", 'outcomes: [done]\nstates:\n  s: {do: log, with: {text: "${in.broken}"}, on: {done: done}}\n'
    )
    result, _ = execute(path, world=CountingWorld())
    assert result.error == "n/s: in.broken: OSError: camera unplugged"


def test_state_and_machine_time_are_rounded_seconds_since_entry(machine: Machine) -> None:
    path = machine(
        "m",
        """
        vars: {st: -1, mt: -1, at: 0}
        outcomes: [done]
        outputs: {st: "${vars.st}", mt: "${vars.mt}", at: "${vars.at}"}
        states:
          first: {do: wait, with: {seconds: 0.3}, on: {done: second}}
          second: {do: set, with: {st: "${state.time}", mt: "${machine.time}", at: "${state.attempt}"}, on: {done: done}}
    """,
    )
    result, _ = execute(path)
    assert result.agents["robot"].outputs == {"st": 0, "mt": 0.3, "at": 1}
