"""`log`: a line in the log (logger `hfsm.log`), with the agent, the state's path and the time."""

from __future__ import annotations

import logging
from typing import Any

from hfsm.builtins.registry import Builtin
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec, ParamSpec

DONE = Event("done")
log = logging.getLogger("hfsm.log")


def start(host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region) -> Event:
    log.info("%s %s t=%s: %s", agent.name, "/".join(where.path()), host.time, params["text"])
    return DONE


LOG = Builtin(
    BehaviourSpec("log", "builtin", {"text": ParamSpec("text", "str")}, ("done",), doc="Log a line."),
    start,
)
