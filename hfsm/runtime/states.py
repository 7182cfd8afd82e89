"""Compiled machines: states with their arcs resolved to objects, timers to ticks, values to closures."""

from __future__ import annotations

import copy
from typing import Any

from hfsm.expr import Fn
from hfsm.primitive import Primitive
from hfsm.spec import BehaviourSpec
from hfsm.values import Value


class Callee:
    """What a call state or a region calls: its behaviour, how to find it, its `with` and `save`."""

    __slots__ = (
        "after", "at", "callee", "do", "kind", "params", "save", "spec", "start", "traced", "wait_ticks",
        "with_",
    )  # fmt: skip

    def __init__(self) -> None:
        self.at: tuple[str | int, ...] = ()  # its path in its machine file: a state's, or a region's
        self.do = ""
        self.kind = ""  # "machine", "primitive", or "builtin"
        self.callee: RMachine | Primitive | None = None
        self.start: Any = None  # a built-in's starter (hfsm/builtins/registry.py)
        self.after: Any = None  # a built-in's activity for a constant span: after(deadline)
        self.traced: tuple[str, ...] = ()  # the outputs the trace shows when it ends (a built-in's trait)
        self.spec: BehaviourSpec | None = None
        self.with_: dict[str, Value] = {}
        self.params: dict[str, Any] | None = None  # the callee's params, when `with` holds no expression
        self.save: tuple[tuple[str, str], ...] = ()
        self.wait_ticks = 0  # > 0: a built-in's constant span, that many ticks (started by `after`)


class RRegion(Callee):
    """One region of a parallel state (docs/REFERENCE.md#parallel-states)."""

    __slots__ = ("background", "index", "name")

    def __init__(self, name: str, index: int) -> None:
        super().__init__()
        self.name = name
        self.index = index
        self.background = False


class JoinRule:
    """`when: {region: outcomes}` as (region index, outcomes) pairs; `else` has none and `is_else`."""

    __slots__ = ("is_else", "target", "text", "when")

    def __init__(self, when: tuple[tuple[int, frozenset[str]], ...], target: RState | str, text: str) -> None:
        self.when = when
        self.target = target
        self.text = text
        self.is_else = text == "else"


class Watch:
    __slots__ = ("condition", "target", "text", "where")

    def __init__(self, condition: Fn, text: str, target: RState | str, where: tuple[str | int, ...]) -> None:
        self.condition = condition
        self.text = text
        self.target = target
        self.where = where  # its condition's path in the machine file


class RState(Callee):
    __slots__ = (
        "arcs",
        "autonomy",
        "awaited",
        "branches",
        "error_target",
        "is_choice",
        "is_parallel",
        "join",
        "join_keys",
        "machine",
        "msg_arcs",
        "name",
        "plain",
        "regions",
        "retry_delay",
        "retry_on",
        "retry_times",
        "scope",
        "stepped",
        "timed",
        "timer",
        "watches",
    )  # fmt: skip

    def __init__(self, name: str, machine: RMachine) -> None:
        super().__init__()
        self.name = name
        self.machine = machine
        self.is_choice = False
        self.is_parallel = False
        self.timer: int | Fn | None = None  # ticks, or an expression giving seconds
        self.arcs: dict[str, RState | str] = {}
        self.msg_arcs: dict[str, RState | str] = {}
        self.error_target: RState | str | None = None
        self.branches: list[tuple[Fn | None, str, RState | str]] = []  # (condition, text, target)
        self.watches: tuple[Watch, ...] = ()  # the machine's, then the state's own
        self.timed = False  # a watch reads the time or an input: the state must be stepped every tick
        self.retry_on: frozenset[str] = frozenset()
        self.retry_times: int | Fn = 0
        self.retry_delay: int | Fn = 0  # ticks, or an expression giving seconds
        self.regions: tuple[RRegion, ...] = ()
        self.awaited: tuple[int, ...] = ()  # indexes of the regions that are not background
        self.join: tuple[JoinRule, ...] = ()
        self.plain = False  # a call state without watches or retry: entered the quick way
        self.stepped = False  # it has watches or a retry: its own level does more in each tick
        self.autonomy: dict[str, int] = {}  # event (or `join:TARGET`) -> the level its arc needs
        self.join_keys: dict[str, str] = {}  # a join rule's event name -> its `join:TARGET`
        self.scope: Any = None  # a `scope:` (docs/REFERENCE.md#scopes): a runtime.scopes.ScopeCode


class RMachine:
    __slots__ = (
        "endings", "initial", "name", "outputs", "spec", "states", "timer", "untraced",
        "var_fresh", "var_init",
    )  # fmt: skip

    def __init__(self, name: str, spec: BehaviourSpec) -> None:
        self.name = name
        self.spec = spec
        self.states: dict[str, RState] = {}
        self.initial: RState | None = None
        self.timer: int | Fn | None = None
        self.var_init: dict[str, Any] = {}
        self.var_fresh = False  # whether initial vars must be deep-copied on each call
        self.untraced: frozenset[str] = frozenset()  # vars the trace does not show
        self.outputs: dict[str, Value] = {}
        self.endings: dict[str, Any] = {}  # outcome -> its Event, shared when there are no outputs

    def fresh_vars(self) -> dict[str, Any]:
        return copy.deepcopy(self.var_init) if self.var_fresh else dict(self.var_init)
