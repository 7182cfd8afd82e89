"""`send`: a message to the others, all, or one agent (qualified by the scope it is sent under)."""

from __future__ import annotations

from typing import Any

from hfsm.builtins.registry import Builtin
from hfsm.names import KEEP, RESERVED_MESSAGES, is_name
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec, ParamSpec


def start(host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region) -> Event:
    name, to, data = params["message"], params.get("to", "others"), params.get("data", {})
    if not is_name(name) or name in RESERVED_MESSAGES:
        return Event("error", error=f"send: bad message name {name!r}")
    problem = host.send(agent, where, name, to, data, params.get("keep", "all"))
    return Event("error", error=problem) if problem else Event("sent")


SEND = Builtin(
    BehaviourSpec(
        "send",
        "builtin",
        {
            "message": ParamSpec("message", "str"),
            "to": ParamSpec("to", "str", required=False, default="others"),
            "data": ParamSpec("data", "dict", required=False, default={}),
            "keep": ParamSpec(
                "keep", "str", required=False, default="all", choices=KEEP,
                doc="'all': every copy waits to be taken; 'last': a status, the newest copy replaces "
                "this sender's copy of the same name not yet taken",
            ),
        },
        ("sent",),
        doc="Send a message to the others, all, or one agent.",
    ),
    start,
    message_param="message",
)
