"""Autonomy levels (SPEC 17): `off` < `low` < `high` < `full`, and the keys of a state's `autonomy:`."""

from __future__ import annotations

from dataclasses import dataclass

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
