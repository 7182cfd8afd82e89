"""Checked machines compiled for running: arcs resolved to objects, timers to ticks, values to closures."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from hfsm.autonomy import join_key, level_of
from hfsm.builtins import REGISTRY
from hfsm.checks.context import machine_spec
from hfsm.expr import TIMED, Fn, Names, compile_expr, reads
from hfsm.library import MachineFile
from hfsm.model import CallState, ChoiceState, IfBranch, JoinRule, Machine, ParallelState, Region, Retry
from hfsm.model import Watch as WatchModel
from hfsm.registry import Registry
from hfsm.runtime.scopes import ScopeCode
from hfsm.runtime.states import Callee, RMachine, RRegion, RState, Watch
from hfsm.runtime.states import JoinRule as RJoin
from hfsm.spec import BehaviourSpec, coerce, is_finite_number, shown, type_ok
from hfsm.values import compile_value

__all__ = ["Program", "RMachine", "RState", "machine_params", "resolve_params", "span_ticks", "timer_ticks"]

Resolve = Callable[[str], "RState | str"]


def span_ticks(seconds: float, dt: float) -> int:
    """Ticks from the tick a span begins to the tick it ends in (docs/REFERENCE.md#time-and-timers)."""
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
                return f"param '{name}' of '{spec.name}' takes {param.type}, not {shown(value)}"
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
        rm.untraced = frozenset(m.untraced)
        rm.timer = self._timer(m.timer, Names(m.params, None))
        names = Names(m.params, m.vars)
        rm.outputs = {k: compile_value(v, names) for k, v in m.outputs.items()}
        rm.states = {n: RState(n, rm) for n in m.states}
        rm.initial = rm.states[m.initial_state]

        def target(name: str) -> RState | str:
            return rm.states.get(name, name)

        any_msgs = {e: target(t) for e, t in m.any.items() if e != "error"}
        any_error = target(m.any["error"]) if "error" in m.any else None
        receives = set(m.receives)
        for name, state in m.states.items():
            rs = rm.states[name]
            rs.error_target = any_error
            rs.at = ("states", name)
            if isinstance(state, ChoiceState):
                rs.is_choice = True
                rs.branches = [
                    (compile_expr(b.condition, names), b.condition, target(b.then))
                    if isinstance(b, IfBranch)
                    else (None, "else", target(b.else_))
                    for b in state.choose
                ]
                continue
            self._arcs(rs, state.on, target, any_msgs, receives)
            rs.timer = self._timer(state.timer, names)
            watches: list[tuple[str | int, ...]] = [("watch", i, "if") for i in range(len(m.watch))]
            watches += [("states", name, "watch", i, "if") for i in range(len(state.watch))]
            self._watches(rs, list(zip([*m.watch, *state.watch], watches, strict=True)), names, target)
            if state.scope is not None:
                rs.scope = ScopeCode(
                    compile_value(state.scope.name, names), compile_value(state.scope.agents, names)
                )
            if isinstance(state, CallState):
                self._callee(rs, state, names)
                rs.save = tuple(state.save.items())
                if state.retry is not None:
                    self._retry(rs, state.retry, Names(m.params, None))
                rs.plain = not rs.watches and not rs.retry_on
            else:
                self._parallel(rs, state, names, target)
            rs.stepped = bool(rs.watches or rs.retry_on)
            rs.autonomy = {event: level_of(level) for event, level in state.autonomy.items()}

    def _callee(self, callee: Callee, call: CallState | Region, names: Names) -> None:
        callee.do = call.do
        machine, prim = self.machines.get(call.do), self.registry.get(call.do)
        callee.callee = machine or prim
        builtin = None if machine or prim else REGISTRY[call.do]
        callee.kind = "machine" if machine else "primitive" if prim else "builtin"
        callee.spec = machine.spec if machine else prim.spec if prim else builtin.spec  # type: ignore[union-attr]
        if builtin is not None:
            callee.start, callee.after, callee.traced = builtin.start, builtin.after, builtin.traced
        callee.with_ = {k: compile_value(v, names) for k, v in call.with_.items()}
        if all(v.constant for v in callee.with_.values()):
            params = resolve_params(callee.spec, {k: v.literal for k, v in callee.with_.items()})
            callee.params = params if isinstance(params, dict) else None
            span = builtin.span_param if builtin is not None and builtin.after is not None else ""
            seconds: Any = callee.params.get(span) if callee.params and span else None
            if is_finite_number(seconds) and seconds > 0:
                callee.wait_ticks = max(0, span_ticks(seconds, self.dt))

    @staticmethod
    def _arcs(
        rs: RState, on: Mapping[str, str], target: Resolve, any_msgs: dict[str, Any], receives: set[str]
    ) -> None:
        rs.msg_arcs = dict(any_msgs)
        for event, to in on.items():
            if event == "error":
                rs.error_target = target(to)
            elif event in receives:
                rs.msg_arcs[event] = target(to)
            else:
                rs.arcs[event] = target(to)
        for event in list(rs.msg_arcs):
            if event in rs.arcs:
                del rs.msg_arcs[event]

    @staticmethod
    def _watches(
        rs: RState, watches: list[tuple[WatchModel, tuple[str | int, ...]]], names: Names, target: Resolve
    ) -> None:
        rs.watches = tuple(
            Watch(compile_expr(w.condition, names), w.condition, target(w.then), at) for w, at in watches
        )
        rs.timed = any(
            name in TIMED or name.startswith("in.") for w, _ in watches for name in reads(w.condition)
        )

    def _retry(self, rs: RState, retry: Retry, names: Names) -> None:
        rs.retry_on = frozenset(retry.on)
        rs.retry_times = (
            compile_expr(retry.times[2:-1], names) if isinstance(retry.times, str) else retry.times
        )
        delay = retry.delay
        rs.retry_delay = (
            compile_expr(delay[2:-1], names) if isinstance(delay, str) else span_ticks(delay, self.dt)
        )

    def _parallel(self, rs: RState, state: ParallelState, names: Names, target: Resolve) -> None:
        rs.is_parallel = True
        regions = []
        for i, (name, region) in enumerate(state.parallel.items()):
            rr = RRegion(name, i)
            rr.at = (*rs.at, "parallel", name)
            self._callee(rr, region, names)
            rr.save = tuple(region.save.items())
            rr.background = region.background
            regions.append(rr)
        rs.regions = tuple(regions)
        rs.awaited = tuple(r.index for r in regions if not r.background)
        index = {r.name: r.index for r in regions}
        rules = []
        for rule in state.join:
            if isinstance(rule, JoinRule):
                when = tuple(
                    (index[region], frozenset([outs] if isinstance(outs, str) else outs))
                    for region, outs in rule.when.items()
                )
                text = ", ".join(
                    f"{r}={'|'.join(o) if isinstance(o, list) else o}" for r, o in rule.when.items()
                )
                rules.append(RJoin(when, target(rule.then), text))
            else:
                rules.append(RJoin((), target(rule.else_), "else"))
            rs.join_keys[rules[-1].text] = join_key(rule.then if isinstance(rule, JoinRule) else rule.else_)
        rs.join = tuple(rules)
