"""`set`: assign the machine's variables (any params, each a variable)."""

from __future__ import annotations

from typing import Any

from hfsm.builtins.registry import Builtin
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec

DONE = Event("done")


def start(host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region) -> Event:
    frame.vars.update(params)
    frame.changed(params)
    return DONE


SET = Builtin(
    BehaviourSpec("set", "builtin", {}, ("done",), open_params=True, doc="Assign variables."), start
)
