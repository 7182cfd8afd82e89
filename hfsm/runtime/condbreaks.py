"""Breakpoints on a condition (`cond:EXPR[@AGENT]`): tried at the end of every tick for each running
agent, over the vars of every machine it runs (the innermost's value of a name shared by several)
and the inputs its machines read in that tick; the run pauses at the start of the next tick when one
turns true (false before its first try). A condition that cannot be evaluated (a var no running
machine has, a type error) is false; one over an input the machines did not read in the tick is not
tried in that tick (it keeps its last value): a condition never asks the world, so it never changes
what the run does."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from hfsm.expr import ExprValueError, Scope
from hfsm.runtime.agent import Agent, frames
from hfsm.runtime.breaks import Breaks
from hfsm.runtime.live import NotRead


def check(breaks: Breaks, agents: Sequence[Agent], tick: int) -> None:
    """Try every condition for every running agent; note the first that turned true as the hit."""
    for point in breaks.points:
        if point.test is None:
            continue
        for agent in agents:
            if agent.result is not None or agent.root is None:
                continue
            if point.agent is not None and agent.name != point.agent:
                continue
            key = (point.text, agent.name)
            now = _holds(point.test, agent, tick)
            if now is None:
                continue
            if now and not breaks.was.get(key, False) and breaks.hit is None:
                breaks.hit = point.text
            breaks.was[key] = now


def _holds(test: Any, agent: Agent, tick: int) -> bool | None:
    """Whether the condition holds for `agent`; None when it reads an input not read in this tick."""
    known: dict[str, Any] = {}
    for frame in frames(agent.root):  # type: ignore[arg-type]
        known.update(frame.vars)
    inputs = _Inputs(agent, tick)
    try:
        return test(Scope({}, known, agent.name, inputs)) is True
    except Exception:  # a condition that cannot be evaluated is false
        return None if inputs.unread else False


class _Inputs:
    """A condition's live names: the inputs the agent's machines read in the tick, and nothing else."""

    def __init__(self, agent: Agent, tick: int) -> None:
        self.agent = agent
        self.tick = tick
        self.unread = False

    def input(self, name: str) -> Any:
        try:
            return self.agent.inputs.peek(name, self.tick)
        except NotRead as exc:
            self.unread = True
            raise ExprValueError(str(exc)) from None

    def state_time(self) -> float:
        raise ExprValueError("'state.time' cannot be read in a condition")

    def state_attempt(self) -> int:
        raise ExprValueError("'state.attempt' cannot be read in a condition")

    def machine_time(self) -> float:
        raise ExprValueError("'machine.time' cannot be read in a condition")

    def scope_name(self) -> str:
        raise ExprValueError("'scope.name' cannot be read in a condition")

    def scope_agents(self) -> list[str]:
        raise ExprValueError("'scope.agents' cannot be read in a condition")
