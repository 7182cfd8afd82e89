"""`wait`: a span of seconds, or (without seconds) until an event or a timer ends it."""

from __future__ import annotations

import math
from typing import Any

from hfsm.builtins.registry import Builtin, Literals
from hfsm.runtime.agent import Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec, ParamSpec

DONE = Event("done")


class Wait:
    __slots__ = ("deadline",)

    def __init__(self, deadline: int | None) -> None:
        self.deadline = deadline

    def advance(self, tick: int) -> Event | None:
        return DONE if self.deadline is not None and tick >= self.deadline else None

    def cancel(self) -> str:
        return ""


def start(
    host: Host, agent: Agent, frame: Frame, params: dict[str, Any], where: Frame | Region
) -> Wait | Event:
    seconds = params["seconds"]
    if seconds is None:
        return Wait(None)
    if seconds <= 0:
        return DONE
    if not math.isfinite(seconds):
        return Event("error", error=f"wait: seconds must be finite, not {seconds}")
    return Wait(host.tick + host.span(seconds))


def blocks(with_: Literals) -> str | None:
    return None if "seconds" in with_ else "'wait' without seconds"


WAIT = Builtin(
    BehaviourSpec(
        "wait",
        "builtin",
        {"seconds": ParamSpec("seconds", "float", required=False, doc="omit: until an event")},
        ("done",),
        doc="Wait for a span of seconds, or until an event or a timer.",
    ),
    start,
    blocks=blocks,
    span_param="seconds",
    after=Wait,
)
