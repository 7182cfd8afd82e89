"""Held arcs: an arc that needs a higher autonomy level than the run's waits for the operator.

A state holds at most one arc (`Frame.held`). While it holds, the state looks at none of its own
other events: its timer, its mapped messages and its watches are not tried, and an end of its callee
is let go; its machine's timer and outer states still act (an outer arc cancels the held one). A
held outcome, error or join rule has ended the callee; a held message (kept out of the mailbox, so
that nothing below can take it) or timer lets the callee go on.
"""

from __future__ import annotations

from collections.abc import Iterator

from hfsm.autonomy import FULL, JOIN, LEVELS
from hfsm.primitive import Message
from hfsm.runtime.agent import HELD, Agent, Event, Frame, frames, leaves
from hfsm.runtime.cancel import Cancelling
from hfsm.runtime.ledger import Ledger
from hfsm.runtime.parts import ArcsPart, RegionsPart
from hfsm.runtime.scopes import short
from hfsm.runtime.states import RState


class Hold:
    """One held arc: the event's key in `autonomy:`, the level it needs, and what takes it."""

    __slots__ = ("event", "index", "key", "level", "message")

    def __init__(
        self, key: str, level: int, event: Event | None, message: Message | None = None, index: int = 0
    ) -> None:
        self.key = key
        self.level = level
        self.event = event  # the ended callee's event (None: a timer's or a message's, the callee runs)
        self.message = message  # a held message, out of the mailbox until its arc is taken or not
        self.index = index  # where it stood in the mailbox


def held_frames(frame: Frame) -> Iterator[Frame]:
    """The frames at and below `frame` that hold an arc, outermost first, regions in their order."""
    return (f for f in frames(frame) if f.held is not None)


def hold_text(agent: Agent) -> str:
    """What an agent holds, for messages: `top/grasp holds 'failed' (needs autonomy high)`."""
    if agent.root is None:
        return ""
    return "; ".join(
        f"{'/'.join(f.path())} holds '{f.held.key}' (needs autonomy {LEVELS[f.held.level]})"
        for f in held_frames(agent.root)
    )


class Holds:
    arcs: ArcsPart
    regions: RegionsPart

    def __init__(self, agents: list[Agent], ledger: Ledger, cancelling: Cancelling) -> None:
        self.agents = agents
        self.ledger = ledger
        self.cancelling = cancelling
        self.level = FULL  # the run's autonomy level
        self.approved: Event | None = None  # the event the operator answered: taken, not held again

    # --- an arc held ---------------------------------------------------------------------------

    def held(self, frame: Frame, state: RState, event: Event) -> bool:
        """Whether `event`, about to take its arc from `frame`'s state, is held instead."""
        if event is HELD or frame.held is not None:
            return True  # held on entry; or it holds another arc, and this end of its callee is let go
        if event is self.approved or event.message is not None:
            return False  # answered by the operator; or a message, looked at before it was taken
        key = state.join_keys.get(event.name) if event.goto is not None else event.name
        need = state.autonomy.get(key) if key is not None else None
        if need is None or self.level >= need:
            return False
        if event.name == "error" and not event.origin:
            event.origin = "/".join(frame.path())
            self.ledger.emit(frame.agent, frame.path(), "error", message=event.error)
        self._hold(frame, Hold(key, need, event))  # type: ignore[arg-type]
        return True

    def timer_held(self, frame: Frame) -> bool:
        """The state's timer fired: whether its `timeout` arc is held (the callee goes on)."""
        need = frame.state.autonomy.get("timeout")
        if need is None or self.level >= need:
            return False
        self.ledger.emit(frame.agent, frame.path(), "timeout", timer="state")
        self._hold(frame, Hold("timeout", need, None))
        return True

    def message_held(self, frame: Frame, state: RState) -> bool:
        """Whether the earliest message the state maps needs a level the run is below: then it is
        kept out of the mailbox, held, and the callee goes on."""
        mailbox = frame.agent.mailbox
        prefix = frame.radio.prefix  # a message under a scope is held by its qualified name
        for i, message in enumerate(mailbox):
            name = message.name
            if prefix and not name.startswith(prefix):
                continue
            bare = name[len(prefix) :]
            if bare in state.msg_arcs:
                need = state.autonomy.get(bare)
                if need is None or self.level >= need:
                    return False
                del mailbox[i]
                self._hold(frame, Hold(name, need, None, message, i))
                return True
        return False

    def _hold(self, frame: Frame, hold: Hold) -> None:
        frame.held = hold
        frame.state_deadline = None  # the state's own timer is not looked at while it holds
        frame.retry_at = None
        self.ledger.emit(frame.agent, frame.path(), "held", event=hold.key, level=LEVELS[hold.level])

    # --- the operator's answers ----------------------------------------------------------------

    def answered(self, agent: Agent, do: str, event: str | None) -> tuple[Frame | None, str]:
        """The state an `accept` or a `force: event` acts on: the agent's outermost holding state,
        else (a force) its deepest running call or parallel state; or why there is none."""
        if agent.root is None or agent.result is not None:
            return None, "the agent has ended"
        frame = next(held_frames(agent.root), None)
        if do == "accept":
            if frame is None:
                return None, "no arc is held"
            if event is not None and event != frame.held.key:
                return None, f"the arc held first is '{frame.held.key}', not '{event}'"
            return frame, ""
        if frame is None:
            leaf = next(leaves(agent.root))
            frame = leaf if leaf.__class__ is Frame else leaf.owner  # type: ignore[union-attr]
        if not event or self._target(frame.state, event) is None:
            mapped = ", ".join(self.events(frame.state))
            return None, f"'{event}' is not an event of {'/'.join(frame.path())} (it maps: {mapped})"
        return frame, ""

    def accept(self, frame: Frame) -> None:
        """The held arc of `frame` taken, in this tick."""
        self._take(frame)

    def force(self, frame: Frame, event: str) -> None:
        """`event`'s arc taken from `frame`'s state instead of what it holds (if it holds)."""
        target = self._target(frame.state, event)
        hold: Hold | None = frame.held
        if hold is not None and hold.message is not None:  # not taken: back where it stood
            mailbox = frame.agent.mailbox
            mailbox.insert(min(hold.index, len(mailbox)), hold.message)
        frame.held = None
        forced = Event(event, goto=target)
        self._answer(frame, self.cancelling.cancelled(frame, event, forced))

    def set_level(self, level: int) -> None:
        """The run's level changes: every held arc whose level is now met is taken, outermost first."""
        self.level = level
        for agent in self.agents:
            while agent.root is not None and agent.result is None:
                frame = next((f for f in held_frames(agent.root) if f.held.level <= level), None)
                if frame is None:
                    break
                self._take(frame)

    @staticmethod
    def events(state: RState) -> list[str]:
        """The events whose arcs the operator may force in `state`."""
        events = [*state.arcs, *state.msg_arcs, *(["error"] if state.error_target is not None else [])]
        return events + [key for key in state.join_keys.values() if key not in events]

    @staticmethod
    def _target(state: RState, event: str) -> RState | str | None:
        if event.startswith(JOIN):
            rule = next((r for r in state.join if state.join_keys.get(r.text) == event), None)
            return None if rule is None else rule.target
        if event == "error":
            return state.error_target
        return state.arcs.get(event) or state.msg_arcs.get(short(event))

    def _take(self, frame: Frame) -> None:
        hold: Hold = frame.held
        frame.held = None
        if hold.event is not None:
            event = hold.event
        elif hold.message is not None:
            event = self.cancelling.cancelled(frame, hold.key, Event(hold.key, message=hold.message))
        else:
            event = self.cancelling.cancelled(frame, "timeout", Event("timeout"))
        self._answer(frame, event)

    def _answer(self, frame: Frame, event: Event) -> None:
        frame.agent.entries = 0
        self.approved = event
        try:
            self.arcs.settle(frame, event)
        finally:
            self.approved = None
        self._joined(frame)

    def _joined(self, frame: Frame) -> None:
        """An answer outside the agent's turn that ended a region: its parallel state's join is tried
        (or its error taken) as after the regions' turn, and so on outwards."""
        while True:
            while frame.up.__class__ is Frame:
                frame = frame.up
            region = frame.up
            if region is None or region.result is None:  # type: ignore[union-attr]
                return
            owner: Frame = region.owner  # type: ignore[union-attr]
            regions = owner.below
            if regions.__class__ is not list or owner.held is not None:
                return
            result: Event = region.result  # type: ignore[union-attr]
            event = (
                self.regions.region_failed(owner, result)
                if result.name == "error"
                else self.regions.join(owner, regions)
            )
            if event is None:
                return
            self.arcs.settle(owner, event)
            frame = owner
