"""Autonomy levels (SPEC 17): `off` < `low` < `high` < `full`, and the keys of a state's `autonomy:`."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from hfsm.names import did_you_mean

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
ACTIONS = AGENT_ACTIONS + RUN_ACTIONS


@dataclass(frozen=True)
class Decision:
    """One record of an operator: at `t` seconds (as `--fail`), `do` for `agent` (`event`, `level`)."""

    t: float
    do: str
    agent: str | None = None
    event: str | None = None
    level: str | None = None


KEYS = ("t", "agent", "do", "event", "level")


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
    return out
