"""What an expression may read (docs/REFERENCE.md#expressions, docs/REFERENCE.md#watches): the names allowed
where it stands, and the scope it runs in."""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from hfsm.expr.text import SHORT, short
from hfsm.names import did_you_mean


class ExprSyntaxError(Exception):
    """An expression that cannot be accepted at load time; `start` and `end` are the offsets of the
    characters at fault in the text given to the compiler (None: the whole expression)."""

    def __init__(self, message: str, start: int | None = None, end: int | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.start = start
        self.end = end if end is not None else start

    def shifted(self, by: int) -> ExprSyntaxError:
        """The same error, its offsets counted from `by` characters earlier (in an enclosing text)."""
        if self.start is None:
            return ExprSyntaxError(self.message, by, by)
        return ExprSyntaxError(self.message, self.start + by, (self.end or self.start) + by)


class ExprValueError(Exception):
    """An expression that failed while running: becomes the event `error`.

    `where`: in a value of several expressions (a dict, a list, a text with several `${…}`), the
    keys and indexes down to the string that failed, then the index of its `${…}` among the string's."""

    where: tuple[str | int, ...] = ()


class Live(Protocol):
    """What changes while a state runs (docs/REFERENCE.md#watches, docs/REFERENCE.md#retries): read only when
    an expression asks."""

    def state_time(self) -> float: ...

    def state_attempt(self) -> int: ...

    def machine_time(self) -> float: ...

    def input(self, name: str) -> Any: ...

    def scope_name(self) -> str: ...

    def scope_agents(self) -> list[str]: ...


class _Nowhere:
    """The live values of a scope outside any running state: reading one is a run-time error."""

    def state_time(self) -> float:
        raise ExprValueError("'state.time' cannot be read here")

    def state_attempt(self) -> int:
        raise ExprValueError("'state.attempt' cannot be read here")

    def machine_time(self) -> float:
        raise ExprValueError("'machine.time' cannot be read here")

    def input(self, name: str) -> Any:
        raise ExprValueError(f"'in.{name}' cannot be read here")

    def scope_name(self) -> str:
        raise ExprValueError("'scope.name' cannot be read here")

    def scope_agents(self) -> list[str]:
        raise ExprValueError("'scope.agents' cannot be read here")


NOWHERE: Live = _Nowhere()


@dataclass(slots=True)
class Scope:
    params: Mapping[str, Any]
    vars: Mapping[str, Any]
    agent: str
    live: Live = NOWHERE


Fn = Callable[[Scope], Any]

IN = "__in__"  # what `in.x` reads as once tokenized: `in` is a Python keyword
ROOTS = ("params", "vars", "agent", "state", "machine", "scope", IN)
LIVE = {"state": ("time", "attempt"), "machine": ("time",), "scope": ("name", "agents")}
BARE_NAMES = ("true", "false", "null", "params", "vars", "agent", "state", "machine", "scope")


@dataclass(frozen=True)
class Names:
    """What an expression may refer to at the place it stands.

    `state`: whether `state.time`/`state.attempt` may be read; `machine_time`: `machine.time`;
    `inputs`: the inputs the run's world declares, or None to accept any `in.x` (checked elsewhere).
    """

    params: Collection[str]
    vars: Collection[str] | None  # None: `vars` may not be read here
    state: bool = True
    machine_time: bool = True
    inputs: Collection[str] | None = None

    def check(self, root: str, name: str) -> None:
        """Refuse `root.name` where it may not be read (the name shortened in the message)."""
        try:
            self._check(root, name)
        except ExprSyntaxError as exc:
            if len(name) <= SHORT:
                raise
            raise ExprSyntaxError(exc.message.replace(name, short(name))) from None

    def _check(self, root: str, attr: str) -> None:
        if root == "agent":
            if attr != "id":
                raise ExprSyntaxError(f"unknown name 'agent.{attr}'; only 'agent.id' exists")
            return
        if root in LIVE:
            self._check_live(root, attr)
            return
        if root == IN:
            if self.inputs is not None and attr not in self.inputs:
                declared = ", ".join(sorted(self.inputs)) or "none"
                hint = did_you_mean(attr, self.inputs)
                raise ExprSyntaxError(f"unknown input 'in.{attr}' (the world declares {declared}){hint}")
            return
        pool = self.params if root == "params" else self.vars
        if pool is None:
            raise ExprSyntaxError(f"'{root}.{attr}': only params and agent.id may be read here")
        if attr not in pool:
            kind = "param" if root == "params" else "variable"
            other, other_root = (self.vars, "vars") if root == "params" else (self.params, "params")
            if other is not None and attr in other:
                hint = f"; did you mean '{other_root}.{attr}'?"
            else:
                hint = did_you_mean(attr, pool)
            raise ExprSyntaxError(f"unknown {kind} '{attr}'{hint}")

    def hint(self, name: str) -> str:
        """A suggestion for a bare name: the var or param of that name, else the closest name."""
        for root, pool in (("vars", self.vars), ("params", self.params)):
            if pool is not None and name in pool:
                return f"; did you mean '{root}.{name}'?"
        qualified = [f"vars.{v}" for v in self.vars or ()] + [f"params.{p}" for p in self.params]
        close = did_you_mean(name, [*BARE_NAMES, *qualified, *(self.vars or ()), *self.params])
        for root, pool in (("vars", self.vars), ("params", self.params)):
            if pool is not None and close and close.split("'")[1] in pool:
                return close.replace("'", f"'{root}.", 1)
        return close

    def _check_live(self, root: str, attr: str) -> None:
        known = LIVE[root]
        if attr not in known:
            close = did_you_mean(attr, known)
            full = [f"'{root}.{k}'" for k in known]
            hint = close.replace("'", f"'{root}.", 1) if close else f"; only {' and '.join(full)}"
            raise ExprSyntaxError(f"unknown name '{root}.{attr}'{hint}")
        if root == "state" and not self.state:
            raise ExprSyntaxError(
                f"'state.{attr}' cannot be read here; only in a state's with, timer and watch, "
                "the machine's watch, and a choice's if"
            )
        if root == "machine" and not self.machine_time:
            raise ExprSyntaxError("'machine.time' cannot be read in the machine's own timer")
