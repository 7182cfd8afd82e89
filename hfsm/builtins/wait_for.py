"""`wait_for`: until a message arrives; its data fields and `sender` are the outputs. With `all`, every
message of that name then in the mailbox is taken at once, oldest first, as the output `messages`
(a list of those dicts): a listener that merges what it hears takes a tick's heartbeats in one state
instead of one state and a drain per message."""

from __future__ import annotations

from typing import Any

from hfsm.builtins.registry import Builtin, Literals, literal
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.runtime.scopes import radio_at
from hfsm.spec import BehaviourSpec, ParamSpec


class WaitFor:
    __slots__ = ("agent", "deadline", "every", "name")

    def __init__(self, agent: Agent, name: str, every: bool = False) -> None:
        self.agent = agent
        self.name = name
        self.every = every
        self.deadline: int | None = None

    def advance(self, tick: int) -> Event | None:
        names = (self.name,)
        message = self.agent.take_message(names)
        if message is None:
            return None
        if not self.every:
            return Event("received", {**message.data, "sender": message.sender})
        messages = [{**message.data, "sender": message.sender}]
        while (message := self.agent.take_message(names)) is not None:
            messages.append({**message.data, "sender": message.sender})
        return Event("received", {"messages": messages})

    def cancel(self) -> str:
        return ""


def start(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> WaitFor | Event:
    activity = WaitFor(agent, radio_at(where).qualify(params["message"]), bool(params.get("all", False)))
    return activity.advance(host.tick) or activity


def blocks(with_: Literals) -> str | None:
    message = literal(with_.get("message"))
    return f"'wait_for' of message '{message}'" if message else "'wait_for'"


def consumes(with_: Literals) -> frozenset[str]:
    message = literal(with_.get("message"))
    return frozenset([message]) if message else frozenset()


WAIT_FOR = Builtin(
    BehaviourSpec(
        "wait_for",
        "builtin",
        {
            "message": ParamSpec("message", "str"),
            "all": ParamSpec(
                "all", "bool", required=False, default=False,
                doc="take every message of that name in the mailbox at once, oldest first: the output "
                "`messages`, a list of {data fields, sender}",
            ),
        },
        ("received",),
        outputs=None,
        doc="Wait until a message arrives; its data fields and `sender` are the outputs (with `all`: "
        "`messages`, every one then waiting, oldest first).",
    ),
    start,
    blocks=blocks,
    consumes=consumes,
    message_param="message",
)
