"""Checked machines compiled for running: arcs resolved to objects, timers to ticks, values to closures."""

from __future__ import annotations

import copy
import math
from collections.abc import Mapping
from typing import Any

from hfsm.builtins import BUILTINS
from hfsm.checks.context import machine_spec
from hfsm.expr import Fn, Names, compile_expr
from hfsm.library import MachineFile
from hfsm.model import CallState, ChoiceState, IfBranch, Machine
from hfsm.primitive import Primitive
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec, coerce, type_ok
from hfsm.values import Value, compile_value


def span_ticks(seconds: float, dt: float) -> int:
    """Ticks from the tick a span begins to the tick it ends in (SPEC section 5)."""
    return math.ceil(seconds / dt - 1e-9)


def timer_ticks(seconds: float, dt: float) -> int:
    """A timer's span in ticks: at least one, so it fires in a later tick than it began."""
    return max(1, span_ticks(seconds, dt))


def resolve_params(spec: BehaviourSpec, given: Mapping[str, Any]) -> dict[str, Any] | str:
    """The params a callee gets: given values typed, defaults filled; or a problem as text."""
    if spec.open_params:
        return dict(given)
    params = {}
    for name, param in spec.params.items():
        if name in given:
            value = given[name]
            if not type_ok(value, param.type):
                return f"param '{name}' of '{spec.name}' takes {param.type}, not {value!r}"
            params[name] = coerce(value, param.type)
        elif not param.required:
            params[name] = param.default
    return params


def machine_params(machine: MachineFile, given: Mapping[str, Any]) -> dict[str, Any]:
    """A top machine's params from Python values: typed, defaults filled (ValueError if wrong)."""
    params = resolve_params(machine_spec(machine), given)
    if isinstance(params, str):
        raise ValueError(params)
    return params


class RState:
    __slots__ = (
        "arcs", "branches", "callee", "do", "error_target", "is_choice", "kind", "machine",
        "msg_arcs", "name", "params", "save", "spec", "timer", "with_",
    )  # fmt: skip

    def __init__(self, name: str, machine: RMachine) -> None:
        self.name = name
        self.machine = machine
        self.is_choice = False
        self.do = ""
        self.kind = ""  # "machine", "primitive", or the built-in's name
        self.callee: RMachine | Primitive | None = None
        self.spec: BehaviourSpec | None = None
        self.with_: dict[str, Value] = {}
        self.params: dict[str, Any] | None = None  # the callee's params, when `with` holds no expression
        self.save: tuple[tuple[str, str], ...] = ()
        self.timer: int | Fn | None = None  # ticks, or an expression giving seconds
        self.arcs: dict[str, RState | str] = {}
        self.msg_arcs: dict[str, RState | str] = {}
        self.error_target: RState | str | None = None
        self.branches: list[tuple[Fn | None, str, RState | str]] = []  # (condition, text, target)


class RMachine:
    __slots__ = ("endings", "initial", "name", "outputs", "spec", "states", "timer", "var_fresh", "var_init")

    def __init__(self, name: str, spec: BehaviourSpec) -> None:
        self.name = name
        self.spec = spec
        self.states: dict[str, RState] = {}
        self.initial: RState | None = None
        self.timer: int | Fn | None = None
        self.var_init: dict[str, Any] = {}
        self.var_fresh = False  # whether initial vars must be deep-copied on each call
        self.outputs: dict[str, Value] = {}
        self.endings: dict[str, Any] = {}  # outcome -> its Event, shared when there are no outputs

    def fresh_vars(self) -> dict[str, Any]:
        return copy.deepcopy(self.var_init) if self.var_fresh else dict(self.var_init)


class Program:
    """Every machine of a run, compiled for one tick length."""

    def __init__(self, machines: Mapping[str, MachineFile], registry: Registry, dt: float) -> None:
        self.dt = dt
        self.registry = registry
        self.machines = {n: RMachine(n, machine_spec(mf)) for n, mf in machines.items()}
        for name, mf in machines.items():
            self._compile(self.machines[name], mf.model)

    def _timer(self, timer: float | str | None, names: Names) -> int | Fn | None:
        if timer is None:
            return None
        if isinstance(timer, str):
            return compile_expr(timer.strip()[2:-1], names)
        return timer_ticks(timer, self.dt)

    def _compile(self, rm: RMachine, m: Machine) -> None:
        rm.var_init = dict(m.vars)
        rm.var_fresh = any(isinstance(v, list | dict) for v in m.vars.values())
        rm.timer = self._timer(m.timer, Names(m.params, None))
        names = Names(m.params, m.vars)
        rm.outputs = {k: compile_value(v, names) for k, v in m.outputs.items()}
        rm.states = {n: RState(n, rm) for n in m.states}
        rm.initial = rm.states[m.initial_state]

        def target(name: str) -> RState | str:
            return rm.states.get(name, name)

        any_msgs = {e: target(t) for e, t in m.any.items() if e != "error"}
        any_error = target(m.any["error"]) if "error" in m.any else None
        for name, state in m.states.items():
            rs = rm.states[name]
            rs.error_target = any_error
            if isinstance(state, CallState):
                self._call_state(rs, state, names, target, any_msgs, set(m.receives))
            elif isinstance(state, ChoiceState):
                rs.is_choice = True
                rs.branches = [
                    (compile_expr(b.condition, names), b.condition, target(b.then))
                    if isinstance(b, IfBranch)
                    else (None, "else", target(b.else_))
                    for b in state.choose
                ]

    def _call_state(
        self,
        rs: RState,
        state: CallState,
        names: Names,
        target: Any,
        any_msgs: dict[str, Any],
        receives: set[str],
    ) -> None:
        rs.do = state.do
        machine, prim = self.machines.get(state.do), self.registry.get(state.do)
        rs.callee = machine or prim
        rs.kind = "machine" if machine else "primitive" if prim else state.do
        rs.spec = machine.spec if machine else prim.spec if prim else BUILTINS[state.do]
        rs.with_ = {k: compile_value(v, names) for k, v in state.with_.items()}
        if all(v.constant for v in rs.with_.values()):
            params = resolve_params(rs.spec, {k: v.literal for k, v in rs.with_.items()})
            rs.params = params if isinstance(params, dict) else None
        rs.save = tuple(state.save.items())
        rs.timer = self._timer(state.timer, names)
        rs.msg_arcs = dict(any_msgs)
        for event, to in state.on.items():
            if event == "error":
                rs.error_target = target(to)
            elif event in receives:
                rs.msg_arcs[event] = target(to)
            else:
                rs.arcs[event] = target(to)
        for event in list(rs.msg_arcs):
            if event in rs.arcs:
                del rs.msg_arcs[event]
