"""The primitive API: a Python function that blocks, as its author sees it, and can be cancelled.

A primitive is declared with `@primitive(...)`; its typed keyword parameters are its params. It gets
a `Context` first. It may block with `ctx.wait(seconds)` / `ctx.wait_until(...)`: the interpreter
runs it in a greenlet and resumes it tick by tick. Cancelling raises `Cancelled` at the blocking
call, so `try/finally` cleans up (a walking robot stops). It returns an outcome name or an
`Outcome` with outputs. Lifecycle, as in py_trees: set up (the world hands `ctx.robot` over),
start (first call), tick (each resume), cancel (`Cancelled`).
"""

from __future__ import annotations

import importlib
import inspect
import logging
import math
import random
import types
import typing
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, Protocol

from hfsm.spec import BehaviourSpec, ParamSpec

_TYPES: dict[Any, str] = {int: "int", float: "float", bool: "bool", str: "str", list: "list", dict: "dict"}


class Cancelled(BaseException):
    """Raised inside a primitive at its blocking call when the interpreter cancels it.

    A BaseException, like GeneratorExit, so that `except Exception` in a primitive does not swallow it.
    """


@dataclass(frozen=True)
class Outcome:
    """What a primitive returns when it has outputs to hand to its caller."""

    name: str
    outputs: Mapping[str, Any] = field(default_factory=dict)

    def __init__(self, name: str, **outputs: Any) -> None:
        object.__setattr__(self, "name", name)
        object.__setattr__(self, "outputs", outputs)


@dataclass(frozen=True)
class Message:
    name: str
    sender: str
    to: str
    data: Mapping[str, Any]
    sent_tick: int
    keep: str = "all"  # "last": replaces the sender's message of the same name not yet taken
    id: int = 0  # the number of its `send` record in the trace (0: none, e.g. an operator's message)


class Context(Protocol):
    """What a primitive sees of the run: clock, agent, mailbox, world handle, logger, randomness."""

    agent: str
    robot: Any
    dt: float
    log: logging.Logger
    rng: random.Random

    @property
    def tick(self) -> int: ...

    @property
    def time(self) -> float: ...

    def wait(self, seconds: float | None = None) -> None:
        """Block for a span of seconds (per docs/REFERENCE.md#time-and-timers), or one tick when None."""

    def wait_until(self, ready: Callable[[], bool], timeout: float = math.inf) -> bool:
        """Block tick by tick until `ready()` is true (True) or the timeout passes (False)."""

    def receive(self, name: str) -> Message | None:
        """Take the earliest message of that name from the mailbox, if any."""

    def send(self, message: str, to: str = "others", *, keep: str = "all", **data: Any) -> None:
        """Send `data` as `message` (`keep`: 'all', or 'last' for a status that replaces the sender's
        copy not yet taken, docs/REFERENCE.md#messages-between-agents)."""

    @property
    def scope(self) -> str:
        """The qualified name of the scope the primitive runs under (REFERENCE.md#scopes; '' outside every
        scope): its messages' names are qualified by it, in `send` and in `receive`."""


PrimitiveFn = Callable[..., "str | Outcome"]


@dataclass(frozen=True)
class Primitive:
    """A declared primitive. `target` is the function, or `"module:function"` imported at first use:
    so commands that only read the declarations (check, list, draw) never import the simulator."""

    spec: BehaviourSpec
    target: PrimitiveFn | str

    @cached_property
    def fn(self) -> PrimitiveFn:
        if not isinstance(self.target, str):
            return self.target
        module, _, attr = self.target.partition(":")
        found = getattr(importlib.import_module(module), attr)
        fn = found.fn if isinstance(found, Primitive) else found
        if not callable(fn):
            raise TypeError(f"primitive '{self.spec.name}': {self.target} is not a function")
        return fn

    @property
    def where(self) -> str:
        """`module:function`, without importing it."""
        if isinstance(self.target, str):
            return self.target
        return f"{self.target.__module__}:{self.target.__qualname__}"


def primitive(
    *,
    outcomes: Iterable[str],
    failures: Iterable[str] | None = None,
    outputs: Iterable[str] = (),
    name: str | None = None,
    world: str | None = None,
) -> Callable[[PrimitiveFn], Primitive]:
    """Declare a primitive from a function `fn(ctx, *, param: type = default, ...)`.

    `failures` defaults, as for machines, to the outcomes named `failure` or `timeout`.
    """
    declared = tuple(outcomes)
    failed = frozenset(o for o in declared if o in ("failure", "timeout")) if failures is None else failures

    def wrap(fn: PrimitiveFn) -> Primitive:
        spec = BehaviourSpec(
            name=name or fn.__name__,
            kind="primitive",
            params=_params_of(fn),
            outcomes=declared,
            failures=frozenset(failed),
            outputs=frozenset(outputs),
            doc=inspect.cleandoc(fn.__doc__ or "").split("\n\n")[0],
            world=world,
        )
        unknown = spec.failures - set(spec.outcomes)
        if unknown:
            raise TypeError(f"{spec.name}: failures {sorted(unknown)} are not outcomes")
        return Primitive(spec, fn)

    return wrap


def _params_of(fn: Callable[..., Any]) -> dict[str, ParamSpec]:
    hints = typing.get_type_hints(fn)
    params: dict[str, ParamSpec] = {}
    for i, p in enumerate(inspect.signature(fn).parameters.values()):
        if i == 0:
            continue  # the context
        if p.kind is not inspect.Parameter.KEYWORD_ONLY:
            raise TypeError(f"{fn.__name__}: parameter '{p.name}' must be keyword-only (after *)")
        type_name = _type_name(hints.get(p.name, Any), fn.__name__, p.name)
        required = p.default is inspect.Parameter.empty
        params[p.name] = ParamSpec(p.name, type_name, required, None if required else p.default)
    return params


def _type_name(hint: Any, fn: str, param: str) -> str:
    origin = typing.get_origin(hint) or hint
    if origin in (typing.Union, types.UnionType):
        args = [a for a in typing.get_args(hint) if a is not type(None)]
        return _type_name(args[0], fn, param) if len(args) == 1 else "any"
    if hint is Any:
        return "any"
    if origin in _TYPES:
        return _TYPES[origin]
    raise TypeError(f"{fn}: parameter '{param}' has type {hint!r}; use int, float, bool, str, list, dict")
