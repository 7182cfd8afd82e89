"""What an expression may read (SPEC 7, 12): the names allowed where it stands, and the scope it runs in."""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

from hfsm.names import did_you_mean


class ExprSyntaxError(Exception):
    """An expression that cannot be accepted at load time."""


class ExprValueError(Exception):
    """An expression that failed while running: becomes the event `error`."""


class Live(Protocol):
    """What changes while a state runs (SPEC 12, 13): read only when an expression asks."""

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

    def check(self, root: str, attr: str) -> None:
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
            raise ExprSyntaxError(f"unknown {kind} '{attr}'{did_you_mean(attr, pool)}")

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
