"""The running code of the built-in behaviours (docs/REFERENCE.md#built-in-behaviours)."""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import Any

from hfsm.names import RESERVED_MESSAGES, is_name
from hfsm.runtime.agent import Activity, Agent, Event, Frame, Region
from hfsm.runtime.barrier import start_barrier
from hfsm.runtime.host import Host
from hfsm.runtime.scopes import radio_at

DONE = Event("done")
log = logging.getLogger("hfsm.log")


class Wait:
    __slots__ = ("deadline",)

    def __init__(self, deadline: int | None) -> None:
        self.deadline = deadline

    def advance(self, tick: int) -> Event | None:
        return DONE if self.deadline is not None and tick >= self.deadline else None

    def cancel(self) -> str:
        return ""


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


def _error(text: str) -> Event:
    return Event("error", error=text)


def start_wait(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> Wait | Event:
    seconds = params["seconds"]
    if seconds is None:
        return Wait(None)
    if seconds <= 0:
        return DONE
    if not math.isfinite(seconds):
        return _error(f"wait: seconds must be finite, not {seconds}")
    return Wait(host.tick + host.span(seconds))


def start_wait_for(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> WaitFor | Event:
    activity = WaitFor(agent, radio_at(where).qualify(params["message"]))
    return activity.advance(host.tick) or activity


def start_send(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> Event:
    name, to, data = params["message"], params.get("to", "others"), params.get("data", {})
    if not is_name(name) or name in RESERVED_MESSAGES:
        return _error(f"send: bad message name {name!r}")
    problem = host.send(agent, where, name, to, data)
    return _error(problem) if problem else Event("sent")


def start_set(host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region) -> Event:
    frame.vars.update(params)
    frame.vars_shown = False
    return DONE


def start_log(host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region) -> Event:
    log.info("%s %s t=%s: %s", agent.name, "/".join(where.path()), host.time, params["text"])
    return DONE


Starter = Callable[[Host, Agent, Frame, dict[str, Any], Frame | Region], Activity | Event]

STARTERS: dict[str, Starter] = {
    "wait": start_wait,
    "wait_for": start_wait_for,
    "send": start_send,
    "set": start_set,
    "log": start_log,
    "barrier": start_barrier,
}
