"""`--operator FILE`: the operator's decisions from a script (YAML) or a trace (`.jsonl`), checked
before anything runs; every problem at its line and column (E360), exit 2."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hfsm.autonomy import KEYS, Decision, decision_of, decision_problems
from hfsm.errors import Finding, UserError
from hfsm.yamlio import Document, decode, read_bytes, read_file

CODE = "E360"


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
    problems = decision_problems(item, agents)
    for key, message in problems:
        bad(key, message)
    if problems:
        return None
    return decision_of(item)


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
