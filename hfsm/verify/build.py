"""What a search runs: the checked machines with stand-ins in the place of every primitive (and of
the machines named), the values stand-ins output and inputs hold, and the bound."""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hfsm.checks.context import machine_spec
from hfsm.errors import UsageError, UserError
from hfsm.load import Loaded
from hfsm.names import did_you_mean
from hfsm.registry import Registry
from hfsm.runtime.program import Program
from hfsm.verify.choices import Decider
from hfsm.verify.standins import stand_in
from hfsm.world import InputSpec
from hfsm.yamlio import read_mapping

DEFAULTS: dict[str, Any] = {"int": 0, "float": 0.0, "bool": False, "str": "", "list": [], "dict": {}}
DEFAULT_BOUND = 600.0


@dataclass
class Values:
    """`--values FILE`: `outputs: {BEHAVIOUR: {NAME: value}}` and `inputs: {NAME: value}`."""

    outputs: dict[str, dict[str, Any]] = field(default_factory=dict)
    inputs: dict[str, Any] = field(default_factory=dict)


def read_values(path: Path | None) -> Values:
    if path is None:
        return Values()
    doc = read_mapping(path, "values")
    values, problems = Values(), []
    for key, value in doc.data.items():
        if key not in ("outputs", "inputs") or not isinstance(value, dict):
            hint = did_you_mean(str(key), ["outputs", "inputs"]) or ""
            problems.append(
                doc.finding((key,), "E373", f"'{key}': outputs or inputs, each a mapping{hint}", key=True)
            )
        elif key == "inputs":
            values.inputs = dict(value)
        else:
            for name, outputs in value.items():
                if not isinstance(outputs, dict):
                    problems.append(doc.finding((key, name), "E373", f"outputs of '{name}': a mapping"))
                else:
                    values.outputs[str(name)] = dict(outputs)
    if problems:
        raise UserError(problems)
    return values


def verify_program(
    loaded: Loaded, registry: Registry, stand_ins: list[str], values: Values, decider: Decider, dt: float
) -> Program:
    unknown = [n for n in stand_ins if n not in loaded.machines]
    if unknown:
        hint = did_you_mean(unknown[0], loaded.machines) or ""
        raise UsageError(f"--stand-in {unknown[0]}: no machine of that name is called{hint}")
    if loaded.roots[0].name in stand_ins:
        raise UsageError("--stand-in: the top machine cannot stand in for itself")
    saved = saved_values(loaded)
    outputs = {n: {**saved.get(n, {}), **values.outputs.get(n, {})} for n in {*saved, *values.outputs}}
    replaced = Registry(stand_in(p.spec, decider, outputs.get(p.spec.name, {})) for p in registry)
    for name in stand_ins:
        replaced.add(stand_in(machine_spec(loaded.machines[name]), decider, outputs.get(name, {})))
    machines = {n: m for n, m in loaded.machines.items() if n not in stand_ins}
    return Program(machines, replaced, dt)


def saved_values(loaded: Loaded) -> dict[str, dict[str, Any]]:
    """A plain value for each output a machine saves into a var: the var's first value (so that a
    stand-in's `talking` saved into a list var is a list), by behaviour and output."""
    found: dict[str, dict[str, Any]] = {}
    for mf in loaded.machines.values():
        model = mf.model
        calls = []
        for state in model.states.values():
            calls.append(state)
            calls.extend((getattr(state, "parallel", None) or {}).values())
        for call in calls:
            do, save = getattr(call, "do", None), getattr(call, "save", None)
            if isinstance(do, str) and isinstance(save, dict):
                for var, output in save.items():
                    if var in model.vars:
                        found.setdefault(do, {}).setdefault(output, model.vars[var])
    return found


def input_values(declared: Mapping[str, Mapping[str, InputSpec]], given: Mapping[str, Any]) -> dict[str, Any]:
    """Every input any world declares, at its type's plain value unless `--values` gives one."""
    found: dict[str, Any] = {}
    for inputs in declared.values():
        for name, spec in inputs.items():
            found.setdefault(name, DEFAULTS.get(spec.type, 0))
    found.update(given)
    return found


_MACHINE_TIME = re.compile(r"\bmachine\s*\.\s*time\b")
_STATE_TIME = re.compile(r"\bstate\s*\.\s*time\b")


def unobserved(loaded: Loaded, watches_time_in_states: bool) -> frozenset[str]:
    """The times a frame keeps that no expression of the run reads: when its machine started (read
    only as `machine.time`) and when its state was entered (`state.time`, and a `left_within`
    property, `watches_time_in_states`). A state's key leaves them out (`canon`). Found by the
    words in the files' text, so a mention anywhere (even in a doc) keeps them."""
    texts = [mf.path.read_text(encoding="utf-8", errors="replace") for mf in loaded.machines.values()]
    found = set()
    if not any(_MACHINE_TIME.search(t) for t in texts):
        found.add("started")
    if not watches_time_in_states and not any(_STATE_TIME.search(t) for t in texts):
        found.add("entered")
    return frozenset(found)


def bound_of(top: Any, given: float | None) -> float:
    """`--bound`, else the top machine's timer when it is a number, else 600 s."""
    if given is not None:
        return given
    timer = top.model.timer
    if isinstance(timer, int | float) and not isinstance(timer, bool):
        return float(timer)
    return DEFAULT_BOUND
