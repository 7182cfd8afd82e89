"""Events and arcs: a state's event taken, the zero-time chain that follows, a machine's end passed up."""

from __future__ import annotations

from hfsm.expr import ExprValueError
from hfsm.runtime.agent import HELD, Event, Frame, Region
from hfsm.runtime.calls import Calls
from hfsm.runtime.core import MAX_ENTRIES, FatalError
from hfsm.runtime.scopes import open_scope, short
from hfsm.runtime.states import RState


class Arcs(Calls):
    def _settle(self, frame: Frame, event: Event) -> None:
        """Hand `event` to `frame`'s state, and each machine's ending to what runs it, up to the top."""
        ended = self._run(frame, event)
        if ended is not None:
            self._pass_up(frame, ended)

    def _pass_up(self, frame: Frame, ended: Event) -> None:
        while True:
            up = frame.up
            if up is None:
                self._end_agent(frame.agent, ended)
                return
            if up.__class__ is Region:
                self._region_ended(up, ended)
                return
            caller: Frame = up  # type: ignore[assignment]
            caller.below = None
            if caller.held is not None:
                return  # its state holds another arc: the callee's end is let go
            if caller.state.retry_on:
                retried = self._retry(caller, ended)
                if retried is None:
                    return
                ended = retried
            after = self._run(caller, ended)
            if after is None:
                return
            frame, ended = caller, after

    def _run(self, frame: Frame, event: Event) -> Event | None:
        """Take arcs in `frame` until its state waits (None) or its machine ends (that ending)."""
        while True:
            state = frame.state
            if state.autonomy and self._held(frame, state, event):
                return None
            name = event.name
            target: RState | str | None
            if event.goto is None and event.message is None and name != "error":
                target = state.arcs.get(name)
                if target is None:
                    error = f"'{state.do}' ended with '{name}', which is not one of its outcomes"
                    event = Event("error", error=error)
                    continue
                if state.save and event.outputs:
                    self._save(frame, state.save, event.outputs)
            else:
                target = self._other_target(frame, state, event)
            if self.records is not None:
                self.records.arc(frame, state, event, target)
            do = state.do
            if do:  # _leave's statistics, without its call
                stats = frame.agent.stats.get(do) or frame.agent.new_stats(do)
                stats.calls += 1
                stats.ticks += self.tick - frame.entered
                stats.events[name] = stats.events.get(name, 0) + 1
            if target is None:
                return event  # an unmapped error ends the machine and passes to its caller
            if target.__class__ is str:
                ending = frame.machine.endings.get(target)  # _finish's work for a machine without outputs
                return ending if ending is not None else self._finish(frame, target)
            entered = self._enter(frame, target)  # type: ignore[arg-type]
            if entered is None:
                return None
            event = entered

    def _other_target(self, frame: Frame, state: RState, event: Event) -> RState | str | None:
        """The target of a choice's branch or a watch (goto), an error, or a message."""
        if event.goto is not None:
            return event.goto
        if event.message is not None and event.name != "error":
            return state.msg_arcs[short(event.name)]
        if not event.origin:
            event.origin = "/".join(frame.path())
            self.emit(frame.agent, frame.path(), "error", message=event.error)
        return state.error_target

    def _enter(self, frame: Frame, state: RState) -> Event | None:
        agent = frame.agent
        frame.state = state
        frame.entered = self.tick
        frame.state_deadline = None
        frame.attempt = 1
        frame.inner = frame.radio
        bad_timer = None if state.timer is None and state.scope is None else self._start_timer(frame, state)
        if self.records is not None:
            self.records.enter(frame, state)
        agent.entries += 1
        if agent.entries > MAX_ENTRIES:
            path = "/".join(frame.path())
            raise FatalError(
                agent.name, f"{path}: more than {MAX_ENTRIES} state entries in one tick", origin=path
            )
        if state.is_choice:
            return self._choose(frame, state)
        if bad_timer is not None:
            return bad_timer
        if agent.mailbox and state.msg_arcs:
            early = self._early_message(frame, state)
            if early is not None:
                return early
        if state.plain:
            return self._start_call(frame, state, frame)
        if state.watches:
            event = self._watch(frame, state)
            if event is not None:
                return event
        if state.is_parallel:
            return self._start_regions(frame)
        event = self._start_call(frame, state, frame)
        if event is not None and state.retry_on:
            return self._retry(frame, event)
        return event

    def _early_message(self, frame: Frame, state: RState) -> Event | None:
        """A message already in the mailbox that the state maps, as its event (HELD: held instead)."""
        if state.autonomy and self._message_held(frame, state):
            return HELD
        message = frame.agent.take_message(state.msg_arcs, frame.radio.prefix)
        return None if message is None else Event(message.name, message=message)

    def _start_timer(self, frame: Frame, state: RState) -> Event | None:
        """The state's timer set (before its `enter` is written, which shows when it fires), then its
        `scope:` read (REFERENCE.md#scopes: what it runs is under it until the state is left); or the error
        either gave, taken once the state is entered."""
        if state.timer is not None:
            ticks = self._ticks(state.timer, frame, (*state.at, "timer"))
            if ticks.__class__ is Event:
                return ticks
            frame.state_deadline = self.tick + ticks  # type: ignore[operator]
        if state.scope is not None:
            radio = open_scope(state.scope, frame.scope, frame.agent.name, frame.radio, self.team.order)
            if isinstance(radio, str):
                return Event("error", error=radio)
            frame.inner = radio
        return None

    def _choose(self, frame: Frame, state: RState) -> Event:
        for i, (condition, text, target) in enumerate(state.branches):
            if condition is None:
                return Event("else", goto=target)
            try:
                if condition(frame.scope):
                    return Event(text, goto=target)
            except ExprValueError as exc:
                return Event("error", error=f"in '{text}': {exc}", where=(*state.at, "choose", i, "if"))
        raise AssertionError("a checked choice ends with else")

    def _watch(self, frame: Frame, state: RState) -> Event | None:
        """The first watch that holds, as the event that takes its arc (None: none holds).

        A watch back to this state is passed over (docs/REFERENCE.md#watches): the state stays, and the
        watches after
        it are tried, so a machine's watch into a state does not silence that state's own."""
        for watch in state.watches:
            try:
                holds = watch.condition(frame.scope)
            except ExprValueError as exc:
                return Event("error", error=f"watch '{watch.text}': {exc}", where=watch.where)
            if holds and watch.target is not state:
                return Event(watch.text, goto=watch.target)
        return None
