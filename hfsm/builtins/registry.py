"""The built-in behaviours' registry: each built-in is one module of this package that declares a
`Builtin` (its signature, its traits, its running code), registered by hfsm/builtins/__init__.py.
Checks, diagrams, the trace and the runtime ask a trait, never a built-in's name (docs/ENGINE.md)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Literal

from hfsm.runtime.agent import Activity, Agent, Event, Frame, Region
from hfsm.runtime.host import Host
from hfsm.spec import BehaviourSpec

Starter = Callable[[Host, Agent, Frame, dict[str, Any], Frame | Region], Activity | Event]
Literals = Mapping[str, Any]  # a call's `with`, as written (an expression stays a string with `${`)


def never(with_: Literals) -> str | None:
    return None


def nothing(with_: Literals) -> frozenset[str]:
    return frozenset()


def literal(value: Any) -> str | None:
    """A `with` value known before the run: a string without an expression."""
    if isinstance(value, str) and "${" not in value:
        return value
    return None


@dataclass(frozen=True)
class Builtin:
    """One built-in behaviour: its signature, how it runs, and what the checks, figures and trace need.

    - `start(host, agent, frame, params, where)`: its activity (an object with `advance(tick)`,
      `cancel()` and `deadline`), or the Event it ends with at once.
    - `blocks(with_)`: why a call with these params can wait without bound (None: it cannot); W403.
    - `consumes(with_)`: the messages it takes from the mailbox (it waits on the radio); W404.
    - `message_param`: a param that names a message, checked as one (E201, E202).
    - `role`: how a figure draws a state that calls it: an ellipse, or a synchronisation bar.
    - `traced`: outputs the trace's `event` record of its ending shows (they vary, so that record is
      never reused as a constant line).
    - `span_param`, `after`: a param of seconds that, when constant, is made ticks when machines are
      compiled; `after(deadline)` is then the activity, started without calling `start`.
    """

    spec: BehaviourSpec
    start: Starter
    blocks: Callable[[Literals], str | None] = never
    consumes: Callable[[Literals], frozenset[str]] = nothing
    message_param: str = ""
    role: Literal["builtin", "barrier"] = "builtin"
    traced: tuple[str, ...] = ()
    span_param: str = ""
    after: Callable[[int], Activity] | None = None

    @property
    def name(self) -> str:
        return self.spec.name


REGISTRY: dict[str, Builtin] = {}
BUILTINS: dict[str, BehaviourSpec] = {}  # the signatures alone, in the order of registration


def register(builtin: Builtin) -> Builtin:
    """Add a built-in (a new name only: a built-in is never replaced)."""
    if builtin.name in REGISTRY:
        raise ValueError(f"built-in '{builtin.name}' is registered twice")
    REGISTRY[builtin.name] = builtin
    BUILTINS[builtin.name] = builtin.spec
    return builtin


def unregister(name: str) -> None:
    """Remove a built-in registered by a test or a plug-in."""
    REGISTRY.pop(name, None)
    BUILTINS.pop(name, None)
