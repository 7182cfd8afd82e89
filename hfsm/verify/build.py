"""What a search runs: the checked machines with stand-ins in the place of every primitive (and of
the machines named), the values stand-ins output and inputs hold, and the bound."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

from hfsm.checks.context import machine_spec
from hfsm.errors import UsageError
from hfsm.expr import ExprSyntaxError, ExprValueError, Names, Scope, compile_expr
from hfsm.load import Loaded
from hfsm.model import Param
from hfsm.names import did_you_mean
from hfsm.registry import Registry
from hfsm.runtime.program import Program
from hfsm.spec import is_finite_number
from hfsm.verify.choices import Decider
from hfsm.verify.standins import stand_in
from hfsm.verify.values import Values
from hfsm.world import InputSpec

DEFAULTS: dict[str, Any] = {"int": 0, "float": 0.0, "bool": False, "str": "", "list": [], "dict": {}}
DEFAULT_BOUND = 600.0


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
    scripts = values.scripts
    replaced = Registry(
        stand_in(p.spec, decider, outputs.get(p.spec.name, {}), scripts.get(p.spec.name, {}))
        for p in registry
    )
    for name in stand_ins:
        spec = machine_spec(loaded.machines[name])
        replaced.add(stand_in(spec, decider, outputs.get(name, {}), scripts.get(name, {})))
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


def bound_of(top: Any, given: float | None, params: Mapping[str, Mapping[str, Any]] = {}) -> float:
    """`--bound`, else the top machine's timer: a number, or an expression worked out with each
    agent's id and params (`params`: agent -> its params; the longest); else 600 s."""
    if given is not None:
        return given
    timer = top.model.timer
    if isinstance(timer, int | float) and not isinstance(timer, bool):
        return float(timer)
    if isinstance(timer, str):
        spans = [_span(timer, top.model.params, agent, p) for agent, p in params.items()]
        found = [s for s in spans if s is not None]
        if found:
            return max(found)
    return DEFAULT_BOUND


def _span(timer: str, declared: Mapping[str, Param], agent: str, given: Mapping[str, Any]) -> float | None:
    """A timer's expression worked out from params alone (the given ones over the defaults); None
    when it reads anything else or does not give a positive number of seconds (the run reports
    that itself)."""
    params = {n: p.default for n, p in declared.items() if not p.required} | dict(given)
    try:
        fn = compile_expr(timer.strip()[2:-1], Names(declared, None, state=False, machine_time=False))
        seconds = fn(Scope(params, {}, agent))
    except (ExprSyntaxError, ExprValueError):
        return None
    return float(seconds) if is_finite_number(seconds) and seconds > 0 else None
