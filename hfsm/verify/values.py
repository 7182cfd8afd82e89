"""`--values FILE`: what stand-ins output and inputs hold. Outputs are given by behaviour
(`outputs: {BEHAVIOUR: {NAME: value}}`) or as hfsm-test's stand-in scripts (`stand_ins:`), whose
steps' outputs are each a set of values a call may end with (their outcomes and durations are not
used: the search chooses those)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hfsm.errors import Finding, UserError
from hfsm.names import did_you_mean
from hfsm.yamlio import Document, read_mapping

KEYS = ("outputs", "inputs", "stand_ins")
STEP_KEYS = ("after", "outcome", "outputs", "doc")
ANY = ""  # the agent of a script that is not by agent (every agent a `by_agent` does not name)

# behaviour -> agent (ANY: any other) -> the outputs of its script's steps, one mapping a step
Scripts = dict[str, dict[str, list[dict[str, Any]]]]


@dataclass
class Values:
    outputs: dict[str, dict[str, Any]] = field(default_factory=dict)
    inputs: dict[str, Any] = field(default_factory=dict)
    scripts: Scripts = field(default_factory=dict)


def read_values(path: Path | None) -> Values:
    if path is None:
        return Values()
    doc = read_mapping(path, "values")
    values, problems = Values(), []
    for key, value in doc.data.items():
        if key not in KEYS or not isinstance(value, dict):
            hint = did_you_mean(str(key), KEYS) or ""
            text = f"'{key}': outputs, inputs or stand_ins, each a mapping{hint}"
            problems.append(doc.finding((key,), "E373", text, key=True))
        elif key == "inputs":
            values.inputs = dict(value)
        elif key == "outputs":
            for name, outputs in value.items():
                if not isinstance(outputs, dict):
                    problems.append(doc.finding((key, name), "E373", f"outputs of '{name}': a mapping"))
                else:
                    values.outputs[str(name)] = dict(outputs)
        else:
            for name, script in value.items():
                values.scripts[str(name)] = _script(doc, (key, name), script, problems)
    if problems:
        raise UserError(problems)
    return values


def _script(
    doc: Document, at: tuple[Any, ...], script: Any, problems: list[Finding]
) -> dict[str, list[dict[str, Any]]]:
    """A stand-in's script as hfsm-test writes it: a step, a list of steps, or `by_agent:`."""
    if isinstance(script, dict) and "by_agent" in script:
        agents = script["by_agent"]
        if len(script) > 1 or not isinstance(agents, dict):
            problems.append(doc.finding(at, "E373", "by_agent: a mapping of agent to script, alone"))
            return {}
        return {str(a): _steps(doc, (*at, "by_agent", a), s, problems) for a, s in agents.items()}
    return {ANY: _steps(doc, at, script, problems)}


def _steps(doc: Document, at: tuple[Any, ...], script: Any, problems: list[Finding]) -> list[dict[str, Any]]:
    steps = script if isinstance(script, list) else [script]
    found: list[dict[str, Any]] = []
    for i, step in enumerate(steps):
        where = (*at, i) if isinstance(script, list) else at
        if not isinstance(step, dict):
            problems.append(doc.finding(where, "E373", "a step: a mapping of after, outcome, outputs"))
            continue
        for key in step:
            if key not in STEP_KEYS:
                hint = did_you_mean(str(key), STEP_KEYS) or ""
                problems.append(
                    doc.finding((*where, key), "E373", f"'{key}': not a key of a step{hint}", key=True)
                )
        outputs = step.get("outputs", {})
        if not isinstance(outputs, dict):
            problems.append(doc.finding((*where, "outputs"), "E373", "outputs: a mapping"))
        elif outputs not in found:
            found.append(dict(outputs))
    return found
