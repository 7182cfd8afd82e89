"""Autonomy levels: `off` < `low` < `high` < `full`, and the keys of a state's `autonomy:`."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from hfsm.names import did_you_mean, is_name

LEVELS = ("off", "low", "high", "full")
FULL = len(LEVELS) - 1
JOIN = "join:"  # a parallel state's rule, by its target: `join:TARGET`


def level_of(name: str) -> int:
    """The rank of a level's name (ValueError if it is not one)."""
    return LEVELS.index(name)


def join_key(target: str) -> str:
    return JOIN + target


AGENT_ACTIONS = ("accept", "force")
RUN_ACTIONS = ("autonomy", "pause", "resume", "step")
ACTIONS = (*AGENT_ACTIONS, *RUN_ACTIONS, "message")  # message: one to an agent, as if from the radio


@dataclass(frozen=True)
class Decision:
    """One record of an operator: at `t` seconds (as `--fail`), `do` for `agent` (`event`, `level`)."""

    t: float
    do: str
    agent: str | None = None
    event: str | None = None
    level: str | None = None
    message: str | None = None
    data: dict[str, Any] | None = None
    hit: str | None = None  # the breakpoint that paused the run (written `break`)


KEYS = ("t", "agent", "do", "event", "level", "message", "data", "break")


def decision_of(item: dict[str, Any]) -> Decision:
    """A checked record (a script's, a trace's, a test's) as a Decision."""
    get = item.get
    return Decision(
        float(item["t"]), item["do"], get("agent"), get("event"), get("level"), get("message"), get("data"),
        get("break"),
    )  # fmt: skip


def decision_problems(item: dict[Any, Any], agents: Sequence[str]) -> list[tuple[str, str]]:
    """What is wrong with one operator record (a script's, a trace's, a test's), as (key, message)."""
    return [*_shape(item), *_fields(item, agents)]


def _shape(item: dict[Any, Any]) -> list[tuple[str, str]]:
    """Unknown keys, the time and the action, as (key, message)."""
    out = [
        (key, f"unknown key '{key}' (an operator record has {', '.join(KEYS)}){did_you_mean(str(key), KEYS)}")
        for key in item
        if key not in KEYS
    ]
    t = item.get("t")
    if isinstance(t, bool) or not isinstance(t, int | float) or not math.isfinite(t) or t < 0:
        out.append(("t", f"t must be a number of seconds >= 0, not {t!r}"))
    do = item.get("do")
    if do not in ACTIONS:
        out.append(
            ("do", f"do must be one of {', '.join(ACTIONS)}, not {do!r}{did_you_mean(str(do), ACTIONS)}")
        )
    return out


def _fields(item: dict[Any, Any], agents: Sequence[str]) -> list[tuple[str, str]]:
    """The agent, event and level each action takes, as (key, message)."""
    do, agent, event, level = item.get("do"), item.get("agent"), item.get("event"), item.get("level")
    out = []
    if do in AGENT_ACTIONS and agent is None:
        out.append(("do", f"'{do}' needs the agent it answers for (agent: …)"))
    if agent is not None and agent not in agents:
        hint = did_you_mean(str(agent), agents) or f" (agents: {', '.join(agents)})"
        out.append(("agent", f"no agent named {agent!r} in this run{hint}"))
    if do == "force" and not isinstance(event, str):
        out.append(("do", "'force' needs the event to take (event: …)"))
    if event is not None and (do not in AGENT_ACTIONS or not isinstance(event, str)):
        out.append(("event", "event is given to 'accept' or 'force' only, as a name"))
    if do == "autonomy" and level not in LEVELS:
        hint = did_you_mean(str(level), LEVELS)
        out.append(
            (
                "level" if "level" in item else "do",
                f"'autonomy' needs a level, one of {', '.join(LEVELS)}, not {level!r}{hint}",
            )
        )
    elif do != "autonomy" and level is not None:
        out.append(("level", "level is given to 'autonomy' only"))
    return out + _message(item)


def _message(item: dict[Any, Any]) -> list[tuple[str, str]]:
    do, name, data = item.get("do"), item.get("message"), item.get("data")
    out = []
    if do == "message":
        if item.get("agent") is None:
            out.append(("do", "'message' needs the agent it is sent to (agent: …)"))
        if not isinstance(name, str) or not is_name(name):
            out.append(
                ("message" if "message" in item else "do", f"'message' needs a message name, not {name!r}")
            )
        if data is not None and not isinstance(data, dict):
            out.append(("data", f"data is a mapping, not {data!r}"))
    else:
        out += [(key, f"{key} is given to 'message' only") for key in ("message", "data") if key in item]
    if "break" in item and (do != "pause" or not isinstance(item["break"], str)):
        out.append(("break", "break names the breakpoint of a 'pause'"))
    return out
