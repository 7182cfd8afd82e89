"""The operator: its decisions, each at the start of a tick, before anything else of it.

A decision comes from a script (`--operator FILE`), a trace's `operator` records, or a live page
(`Operator.live`, fed from another thread). Each is written to the trace as an `operator` record at
the time it took effect, so that a run replays exactly from its own trace. While paused the clock
stands at the tick that has not run yet: only a decision due by then can resume or step it.
"""

from __future__ import annotations

import queue
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from hfsm.autonomy import AGENT_ACTIONS, Decision, level_of
from hfsm.primitive import Message
from hfsm.runtime.core import FatalError
from hfsm.runtime.program import span_ticks

OPERATOR = "operator"  # the sender of a message the operator sends

if TYPE_CHECKING:
    from hfsm.runtime.agent import Frame
    from hfsm.runtime.engine import Engine


class Operator:
    """The decisions of one run, applied at the start of the ticks they are due in."""

    def __init__(
        self, engine: Engine, decisions: Sequence[Decision], live: queue.Queue[Decision] | None = None
    ):
        self.engine = engine
        self.due = sorted(
            ((span_ticks(d.t, engine.dt), i, d) for i, d in enumerate(decisions)), key=lambda due: due[:2]
        )
        self.live = live
        self.pending: list[Decision] = []  # live decisions that came while the run waited for one
        self.paused = False
        self.stepping = False  # paused, but one tick runs
        self.busy = True  # whether the run must look at the operator in its next tick
        self._update()

    def _update(self) -> None:
        self.busy = bool(self.due or self.pending or self.paused or self.stepping) or (
            self.live is not None or self.engine.breaks is not None
        )

    def next_due(self) -> int | None:
        """The tick of the next scripted decision (a static world's run does not skip past it)."""
        return self.due[0][0] if self.due else None

    def apply(self, tick: int) -> None:
        """Every decision due by `tick`, in order, then those a live page has sent."""
        breaks = self.engine.breaks
        if breaks is not None and breaks.hit is not None:
            hit, breaks.hit = breaks.hit, None
            self._act(Decision(0.0, "pause", hit=hit))
        while self.due and self.due[0][0] <= tick:
            self._act(self.due.pop(0)[2])
        while self.pending:
            self._act(self.pending.pop(0))
        if self.live is not None:
            while True:
                try:
                    decision = self.live.get_nowait()
                except queue.Empty:
                    break
                self._act(decision)
        self._update()

    def hit(self) -> bool:
        """Whether a breakpoint matched: the next tick pauses the run."""
        breaks = self.engine.breaks
        return breaks is not None and breaks.hit is not None

    def wait_live(self) -> None:
        """Nothing else can happen: wait for the live operator's next decision (or a stop signal)."""
        self.pending.append(self._next_live())

    def _next_live(self) -> Decision:
        stopping = getattr(self.engine.world, "stopping", None)
        while True:
            try:
                return self.live.get(timeout=0.2)  # type: ignore[union-attr]
            except queue.Empty:
                if stopping is not None and stopping():
                    raise FatalError("", "stopped while waiting for the operator") from None

    def hold_on(self, tick: int) -> str:
        """While paused (and not stepping) at `tick`: apply what comes, until the run may go on
        (''), or why it never will (no decision left to resume or step it)."""
        while self.paused and not self.stepping:
            if self.due and self.due[0][0] <= tick:
                self._act(self.due.pop(0)[2])
            elif self.live is not None:
                self._act(self._next_live())
            else:
                return f"paused at t={self.engine.time:g} s, and no operator record resumes or steps it"
        self._update()
        return ""

    def ran(self) -> None:
        """A tick ran: a step is spent."""
        self.stepping = False

    def _act(self, decision: Decision) -> None:
        """Write the decision's record, then do it (unless it cannot be done: `ignored` says why)."""
        engine = self.engine
        record: dict[str, Any] = {"t": engine.time, "agent": decision.agent, "path": [], "kind": "operator"}
        record["do"] = decision.do
        if decision.hit is not None:
            record["break"] = decision.hit  # a breakpoint paused the run
        frame, why = self._acts_on(decision, record)
        if why:
            record["ignored"] = why
        if engine.records is not None:
            engine.records.put(record)
        if not why:
            self._do(decision, frame)

    def _acts_on(self, decision: Decision, record: dict[str, Any]) -> tuple[Frame | None, str]:
        """The state an agent's decision acts on (its path, event or level recorded), or why none."""
        do = decision.do
        if do == "autonomy":
            record["level"] = decision.level
        if do == "message":
            record["message"], record["data"] = decision.message, decision.data or {}
            known = decision.agent in self.engine.by_name
            return None, "" if known else f"no agent named '{decision.agent}'"
        if do not in AGENT_ACTIONS:
            return None, "the run is not paused" if do == "step" and not self.paused else ""
        record["event"] = decision.event
        agent = self.engine.by_name.get(decision.agent or "")
        if agent is None:
            return None, f"no agent named '{decision.agent}'"
        frame, why = self.engine.answered(agent, do, decision.event)
        record["path"] = frame.path() if frame is not None else [agent.top]
        return frame, why

    def _do(self, decision: Decision, frame: Frame | None) -> None:
        do = decision.do
        if do == "pause":
            self.paused = True
        elif do == "resume":
            self.paused = self.stepping = False
        elif do == "step":
            self.stepping = True
        elif do == "autonomy":
            self.engine.set_level(level_of(decision.level or ""))
        elif do == "message":  # into the mailbox now, as the radio delivers at the start of a tick
            message = Message(
                decision.message or "",
                OPERATOR,
                decision.agent or "",
                dict(decision.data or {}),
                self.engine.tick,
            )
            self.engine.deliver([message])
        elif do == "accept":
            self.engine.accept(frame)  # type: ignore[arg-type]
        else:
            self.engine.force(frame, decision.event or "")  # type: ignore[arg-type]
