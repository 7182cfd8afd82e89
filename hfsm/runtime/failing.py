"""Agents that fail (docs/REFERENCE.md#agents-that-fail): the world or `--fail` stops an agent at the start
of a tick.

From that tick on the agent acts no more: what it runs is cancelled (it cleans up), it sends
nothing, messages and notices to it are lost, and the trace writes one `failed` record.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from hfsm.runtime.agent import Agent, AgentResult, leaves
from hfsm.runtime.program import span_ticks

if TYPE_CHECKING:
    from hfsm.runtime.engine import Engine

FAIL_REASON = "--fail"


@dataclass(frozen=True)
class Failure:
    """An agent to fail at the tick in which a span of `seconds` begun in tick 0 ends."""

    agent: str
    seconds: float
    reason: str = FAIL_REASON


class Failures:
    """The failures of one run: those scheduled by the run's options, and those the world decides."""

    def __init__(self, engine: Engine, scheduled: Sequence[Failure]) -> None:
        self.engine = engine
        unknown = sorted({f.agent for f in scheduled} - set(engine.by_name))
        if unknown:
            raise ValueError(f"no agent named {', '.join(unknown)} to fail")
        self.due = sorted(
            ((span_ticks(f.seconds, engine.dt), f.agent, f.reason) for f in scheduled),
            key=lambda due: due[0],
        )

    def apply(self, tick: int) -> None:
        """Fail the agents due at the start of `tick`, before messages enter the mailboxes.

        The run calls it only while failures are scheduled or the world is not static: a static
        world fails no agent on its own.
        """
        engine = self.engine
        while self.due and self.due[0][0] <= tick:
            _, name, reason = self.due.pop(0)
            fail(engine, engine.by_name[name], reason)
        if not engine.world.static:
            for name, reason in engine.world.failures(tick):
                fail(engine, engine.by_name[name], reason)


def fail(engine: Engine, agent: Agent, reason: str) -> None:
    if agent.failed is not None:
        return
    agent.failed = reason
    agent.mailbox.clear()
    engine.world.fail(agent.name)  # first: the clean-up that follows finds its body stopped
    path = next(leaves(agent.root)).path() if agent.root is not None else [agent.top]
    engine.emit(agent, path, "failed", reason=reason)
    if agent.result is not None:
        return  # it had ended: its result stands, and from now on it no longer answers
    engine.stop(agent, "failed")
    engine.running -= 1
    agent.result = AgentResult(None, {}, engine.time, failed=reason)


def all_failed(agents: Sequence[Agent]) -> bool:
    return all(a.result is not None and a.result.failed is not None for a in agents)
