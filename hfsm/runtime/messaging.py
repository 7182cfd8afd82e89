"""The radio (docs/REFERENCE.md#messages-between-agents): messages sent under a scope's name,
delivered into mailboxes or to the team's barriers, and a state's mapped message taking its arc."""

from __future__ import annotations

from typing import Any

from hfsm.names import KEEP
from hfsm.primitive import Message
from hfsm.runtime.agent import Agent, Event, Frame, Region, leaves
from hfsm.runtime.cancel import Cancelling
from hfsm.runtime.clock import RunClock
from hfsm.runtime.ledger import Ledger
from hfsm.runtime.parts import ArcsPart, HoldsPart
from hfsm.runtime.scopes import radio_at
from hfsm.runtime.scopes import targets as scoped_targets
from hfsm.runtime.states import RState
from hfsm.runtime.team import Team
from hfsm.world import NOTICE, World


class Messaging:
    arcs: ArcsPart
    holds: HoldsPart

    def __init__(
        self,
        agents: list[Agent],
        world: World,
        team: Team,
        clock: RunClock,
        ledger: Ledger,
        cancelling: Cancelling,
    ) -> None:
        self.agents = agents
        self.by_name = {a.name: a for a in agents}
        self.world = world
        self.team = team
        self.clock = clock
        self.ledger = ledger
        self.cancelling = cancelling
        self.sent = 0  # messages sent in the run: a `send` record's id, which its `receive`s give

    def send(
        self, agent: Agent, where: Frame | Region, name: str, to: str, data: dict[str, Any], keep: str = "all"
    ) -> str:
        """Post a message, its name qualified by the scope it is sent under; a problem as text, or ''."""
        if keep not in KEEP:
            return f"send: keep must be {' or '.join(repr(k) for k in KEEP)}, not {keep!r}"
        radio = radio_at(where)
        if not radio.top:
            chosen = scoped_targets(radio, agent.name, to)
            if isinstance(chosen, str):
                return chosen
            targets = chosen
            name = radio.prefix + name
        elif to == "others":
            targets = [a.name for a in self.agents if a is not agent]
        elif to == "all":
            targets = [a.name for a in self.agents]
        elif to in self.by_name:
            targets = [to]
        else:
            return f"send: no agent named '{to}' (agents: {', '.join(self.by_name)})"
        self.sent += 1
        number = self.sent
        if self.ledger.records is not None:
            extra = {"keep": keep} if keep != "all" else {}
            self.ledger.emit(agent, where.path(), "send", message=name, to=to, data=data, id=number, **extra)
        for target in targets:
            self.world.post(Message(name, agent.name, target, dict(data), self.clock.tick, keep, number))
        return ""

    def deliver(self, messages: list[Message]) -> None:
        paths: dict[str, list[str]] = {}  # where each agent runs: the same for all its messages
        for message in messages:
            agent = self.by_name.get(message.to)
            if agent is None or agent.failed is not None:
                continue  # lost: nobody hears it
            if message.name == NOTICE:
                self.team.receive(message)
                continue
            if agent.result is not None:
                continue  # the agent has ended: nobody will take it
            if message.keep == "last":
                replaced = agent.mailbox.replace(message)
            else:
                agent.mailbox.append(message)
                replaced = False
            if self.ledger.records is not None:
                path = paths.get(agent.name) or paths.setdefault(agent.name, _first_leaf(agent))
                self.ledger.records.receive(agent, path, message, replaced)

    def message_arc(self, frame: Frame, state: RState) -> bool:
        """The earliest message the state maps takes its arc (or is held): whether one did. A state
        that holds an arc looks at no message."""
        if frame.held is not None:
            return False
        if state.autonomy and self.holds.message_held(frame, state):
            return True
        message = frame.agent.take_message(state.msg_arcs, frame.radio.prefix)
        if message is None:
            return False
        event = Event(message.name, message=message)
        self.arcs.settle(frame, self.cancelling.cancelled(frame, message.name, event))
        return True


def _first_leaf(agent: Agent) -> list[str]:
    if agent.root is None:
        return [agent.top]
    return next(leaves(agent.root)).path()
