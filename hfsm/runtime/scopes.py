"""Scopes: the private radio a state gives what it runs, and message names qualified by it.

Each running machine frame knows the radio its machine runs under (`Frame.radio`) and the one its
current state gives its behaviour (`Frame.inner`: a new one when the state has a `scope:`, else the
same). Outside every scope an agent's radio is the run's (`top`), with every other agent.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hfsm.expr import ExprValueError
from hfsm.names import did_you_mean, is_name
from hfsm.values import Value


class Radio:
    """A scope as one agent sees it: its qualified name, its partners in run order, the prefix of names."""

    __slots__ = ("agents", "name", "prefix", "top")

    def __init__(self, name: str, agents: tuple[str, ...], *, top: bool = False) -> None:
        self.name = name
        self.agents = agents
        self.prefix = f"{name}/" if name else ""
        self.top = top

    def qualify(self, name: str) -> str:
        return self.prefix + name if self.prefix else name


class ScopeCode:
    """A state's compiled `scope:`: its name and its agents, each a literal or an expression."""

    __slots__ = ("agents", "name")

    def __init__(self, name: Value, agents: Value) -> None:
        self.name = name
        self.agents = agents


def short(name: str) -> str:
    """A qualified message name without its scope: what the machine's `on:` maps."""
    return name[name.rfind("/") + 1 :]


def open_scope(code: ScopeCode, read: Any, me: str, outer: Radio, order: Mapping[str, int]) -> Radio | str:
    """The radio a state's `scope:` gives (read with the state's machine's expression scope `read`),
    or a problem as text. `order` is every agent the run knows, in run order."""
    try:
        name, agents = code.name.fn(read), code.agents.fn(read)
    except ExprValueError as exc:
        return f"scope: {exc}"
    if not isinstance(name, str) or not is_name(name):
        return f"scope: name {name!r} is not a name (a-z, 0-9, _; starting with a letter)"
    if not isinstance(agents, list) or not all(isinstance(a, str) for a in agents):
        return f"scope '{name}': agents must be a list of agent ids, not {agents!r}"
    enclosing = set(outer.agents) | {me} if not outer.top else set(order)
    for agent in agents:
        if agent not in enclosing:
            where = "the run" if outer.top else f"scope '{outer.name}'"
            known = sorted(enclosing, key=order.__getitem__)
            hint = did_you_mean(agent, known) or f" (agents: {', '.join(known)})"
            return f"scope '{name}': no agent named {agent!r} in {where}{hint}"
    members = tuple(sorted({a for a in agents if a != me}, key=order.__getitem__))
    return Radio(outer.prefix + name, members)


def targets(radio: Radio, me: str, to: str) -> list[str] | str:
    """The agents a `send` under `radio` goes to (docs/REFERENCE.md#scopes), or a problem as text."""
    if to == "others":
        return list(radio.agents)
    if to == "all":
        return [*radio.agents, me]
    if to == me or to in radio.agents:
        return [to]
    known = [*radio.agents, me]
    return f"send: no agent named '{to}' in scope '{radio.name}' (agents: {', '.join(known)})"


def members(radio: Radio, me: str, named: list[Any]) -> list[str] | str:
    """The agents a `barrier` under `radio` waits for: `agents: []` means the scope's; or a problem."""
    if not named:
        return list(radio.agents)
    for other in named:
        if other == me:
            return f"names the agent itself ('{me}')"
        if not isinstance(other, str) or other not in radio.agents:
            hint = did_you_mean(other, radio.agents) if isinstance(other, str) else ""
            return f"no agent named {other!r} in scope '{radio.name}'" + (
                hint or f" (agents: {', '.join(radio.agents)})"
            )
    if len(set(named)) != len(named):
        return "names an agent twice"
    return [a for a in radio.agents if a in named]


def radio_at(where: Any) -> Radio:
    """The scope a behaviour runs under: its call state's (a frame's `inner`), or its region's."""
    inner: Radio | None = getattr(where, "inner", None)
    return inner if inner is not None else where.owner.inner


def run_under(agents: list[Any], scopes: Mapping[str, tuple[str, tuple[str, ...]]]) -> None:
    """An agent's top machine runs under the scope `scopes` gives it, (name, agents), each agent
    leaving itself out, as if called by a state with that `scope:`: a run of a machine written for
    a pair (a behaviour test, a room of pairs told their partners)."""
    for agent in agents:
        if agent.name in scopes:
            name, members = scopes[agent.name]
            agent.radio = Radio(name, tuple(m for m in members if m != agent.name))
