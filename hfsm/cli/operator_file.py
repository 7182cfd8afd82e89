"""`--operator FILE`: the operator's decisions from a script (YAML) or a trace (`.jsonl`), checked
before anything runs; every problem at its line and column (E360), exit 2."""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hfsm.autonomy import ACTIONS, AGENT_ACTIONS, LEVELS, Decision
from hfsm.errors import Finding, UserError
from hfsm.names import did_you_mean
from hfsm.yamlio import Document, decode, read_bytes, read_file

CODE = "E360"
KEYS = ("t", "agent", "do", "event", "level")


def read_decisions(path: Path, agents: Sequence[str]) -> list[Decision]:
    """The decisions of a script, or the `operator` records of a trace (a file ending `.jsonl`)."""
    if path.suffix == ".jsonl":
        return _from_trace(path, agents)
    doc = read_file(path)
    if not isinstance(doc.data, list):
        raise UserError(
            [doc.finding((), CODE, "an operator script is a list of {t, agent, do, event, level}")]
        )
    found: list[Finding] = []
    decisions = []
    for i, item in enumerate(doc.data):
        decision = _decision(item, agents, lambda key, message, i=i: found.append(_at(doc, i, key, message)))
        if decision is not None:
            decisions.append(decision)
    if found:
        raise UserError(found)
    return decisions


def _at(doc: Document, i: int, key: str | None, message: str) -> Finding:
    path: tuple[str | int, ...] = (i,) if key is None else (i, key)
    return doc.finding(path, CODE, message, key=key is not None and key not in (doc.data[i] or {}))


def _decision(item: Any, agents: Sequence[str], bad: Any) -> Decision | None:
    """One record checked (each problem told to `bad(key, message)`), or None if it is wrong."""
    if not isinstance(item, dict):
        bad(None, "an operator record is a mapping {t, agent, do, event, level}")
        return None
    problems = [*_shape(item), *_fields(item, agents)]
    for key, message in problems:
        bad(key, message)
    if problems:
        return None
    return Decision(float(item["t"]), item["do"], item.get("agent"), item.get("event"), item.get("level"))


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


def _from_trace(path: Path, agents: Sequence[str]) -> list[Decision]:
    file = str(path)
    text = decode(read_bytes(path, file), file)
    found: list[Finding] = []
    decisions = []
    for n, line in enumerate(text.splitlines(), 1):
        if '"operator"' not in line:
            continue
        try:
            record = json.loads(line)
        except ValueError as exc:
            found.append(Finding(file, n, 1, CODE, f"not a JSON record: {exc}"))
            continue
        if not isinstance(record, dict) or record.get("kind") != "operator":
            continue
        item = {k: record[k] for k in KEYS if record.get(k) is not None}
        decision = _decision(
            item,
            agents,
            lambda key, message, n=n: found.append(Finding(file, n, 1, CODE, f"operator record: {message}")),
        )
        if decision is not None:
            decisions.append(decision)
    if found:
        raise UserError(found)
    return decisions
