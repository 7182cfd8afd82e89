"""`wait_for`: until a message arrives; its data fields and `sender` are the outputs."""

from __future__ import annotations

from typing import Any

from hfsm.builtins.registry import Builtin, Literals, literal
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.runtime.scopes import radio_at
from hfsm.spec import BehaviourSpec, ParamSpec


class WaitFor:
    __slots__ = ("agent", "deadline", "name")

    def __init__(self, agent: Agent, name: str) -> None:
        self.agent = agent
        self.name = name
        self.deadline: int | None = None

    def advance(self, tick: int) -> Event | None:
        message = self.agent.take_message((self.name,))
        if message is None:
            return None
        return Event("received", {**message.data, "sender": message.sender})

    def cancel(self) -> str:
        return ""


def start(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> WaitFor | Event:
    activity = WaitFor(agent, radio_at(where).qualify(params["message"]))
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
        {"message": ParamSpec("message", "str")},
        ("received",),
        outputs=None,
        doc="Wait until a message arrives; its data fields and `sender` are the outputs.",
    ),
    start,
    blocks=blocks,
    consumes=consumes,
    message_param="message",
)
