"""The peers of bench_engine: one adapter per library over shared machine descriptions.

Workloads as docs/PERFORMANCE.md describes them:
- W1 flat: A <-> B on `toggle`;
- W2 nested: root > {P, Q} > {P1, P2 | Q1, Q2} > {P1a, P1b, ...}; `go` is declared on P and Q and
  fired while a leaf is active, so each dispatch exits 3 states and enters 3; every state counts its
  entries and exits in a callback; `alt` arcs (never fired) make every state reachable;
- W3 chain: s0 -> s1 -> ... -> s499 -> end on `next` (and `reset`, never fired, back to s0, since
  python-statemachine rejects a non-final state without arcs); built from YAML in the library's own schema
  (timed, one build), and run (µs per transition).
An adapter builds a machine from a description, gives a zero-argument `stepper` that dispatches one
event by name and runs it to completion, and reports the active leaf and the callback counts.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial
from itertools import pairwise
from typing import Any, Protocol

import yaml

Step = Callable[[], Any]
Arc = tuple[str, tuple[Step, ...], tuple[Step, ...]]  # target leaf, exit callbacks, entry callbacks


@dataclass(frozen=True)
class Spec:
    """States as a tree (parent -> ordered children, the first is initial; root ''), arcs, callbacks."""

    children: dict[str, list[str]]
    arcs: list[tuple[str, str, str]]  # (event, source, target)
    callbacks: bool = False

    def parent(self, state: str) -> str:
        return next(p for p, kids in self.children.items() if state in kids)

    def path(self, state: str) -> list[str]:
        """The state's ancestors from the top level down to the state itself."""
        chain = [state]
        while (up := self.parent(chain[0])) != "":
            chain.insert(0, up)
        return chain

    def initial_leaf(self, state: str) -> list[str]:
        """`state`, then its initial child, and so on down to a leaf."""
        out = [state]
        while out[-1] in self.children:
            out.append(self.children[out[-1]][0])
        return out

    def leaves(self) -> list[str]:
        inner = set(self.children)
        return [s for kids in self.children.values() for s in kids if s not in inner]


def flat_spec() -> Spec:
    return Spec({"": ["A", "B"]}, [("toggle", "A", "B"), ("toggle", "B", "A")])


def nested_spec() -> Spec:
    children: dict[str, list[str]] = {"": ["P", "Q"]}
    arcs = [("go", "P", "Q"), ("go", "Q", "P")]
    for top in ("P", "Q"):
        children[top] = [f"{top}1", f"{top}2"]
        arcs.append(("alt", f"{top}1", f"{top}2"))
        for mid in children[top]:
            children[mid] = [f"{mid}a", f"{mid}b"]
            arcs.append(("alt", f"{mid}a", f"{mid}b"))
    return Spec(children, arcs, callbacks=True)


def chain_spec(states: int = 500) -> Spec:
    """`next` from s0 to `end`; `reset` (never fired) from `end` back, so no state is a trap."""
    names = [f"s{i}" for i in range(states)] + ["end"]
    arcs = [("next", a, b) for a, b in pairwise(names)]
    return Spec({"": names}, [*arcs, ("reset", "end", "s0")])


@dataclass
class Counter:
    entries: int = 0
    exits: int = 0

    def enter(self, *args: Any, **kwargs: Any) -> None:
        self.entries += 1

    def exit(self, *args: Any, **kwargs: Any) -> None:
        self.exits += 1


@dataclass
class Built:
    machine: Any
    counter: Counter = field(default_factory=Counter)


class Adapter(Protocol):
    name: str
    dist: str  # the distribution whose version is reported ('' for none)

    def build(self, spec: Spec) -> Built: ...

    def stepper(self, built: Built, event: str) -> Step: ...

    def leaf(self, built: Built) -> str: ...

    def chain_yaml(self, spec: Spec) -> str: ...

    def from_yaml(self, text: str) -> Built: ...


def _dump(doc: Any) -> str:
    return yaml.dump(doc, Dumper=yaml.CSafeDumper, sort_keys=False)


def _parse(text: str) -> Any:
    return yaml.load(text, Loader=yaml.CSafeLoader)


# --- floor: a dict table -------------------------------------------------------------------------


class FlatTable:
    def __init__(self, table: dict[str, dict[str, str]], initial: str) -> None:
        self.table = table
        self.state = initial

    def send(self, event: str) -> None:
        self.state = self.table[self.state][event]


class NestedTable:
    """(leaf, event) -> (target leaf, exit callbacks, entry callbacks), precompiled at build time."""

    def __init__(self, table: dict[str, dict[str, Arc]], leaf: str) -> None:
        self.table = table
        self.state = leaf

    def send(self, event: str) -> None:
        target, exits, entries = self.table[self.state][event]
        for f in exits:
            f()
        for f in entries:
            f()
        self.state = target


def _compiled_arc(spec: Spec, leaf: str, target: str, counter: Counter) -> Arc:
    here, there = spec.path(leaf), spec.path(target)
    common = 0
    while common < min(len(here), len(there)) and here[common] == there[common]:
        common += 1
    common = min(common, len(there) - 1)  # an arc to an ancestor leaves and re-enters it
    entered = there[common:] + spec.initial_leaf(target)[1:]
    exits = tuple(counter.exit for _ in here[common:])
    return entered[-1], exits, tuple(counter.enter for _ in entered)


class Floor:
    name = "floor (dict table)"
    dist = ""

    def build(self, spec: Spec) -> Built:
        if not spec.callbacks:
            table: dict[str, dict[str, str]] = {}
            for event, source, target in spec.arcs:
                table.setdefault(source, {})[event] = target
            return Built(FlatTable(table, spec.children[""][0]))
        counter = Counter()
        nested: dict[str, dict[str, Any]] = {}
        for leaf in spec.leaves():
            arcs = nested[leaf] = {}
            for state in reversed(spec.path(leaf)):  # innermost handler wins
                for event, source, target in spec.arcs:
                    if source == state and event not in arcs:
                        arcs[event] = _compiled_arc(spec, leaf, target, counter)
        return Built(NestedTable(nested, spec.initial_leaf(spec.children[""][0])[-1]), counter)

    def stepper(self, built: Built, event: str) -> Step:
        return partial(built.machine.send, event)

    def leaf(self, built: Built) -> str:
        return str(built.machine.state)

    def chain_yaml(self, spec: Spec) -> str:
        table: dict[str, dict[str, str]] = {}
        for event, source, target in spec.arcs:
            table.setdefault(source, {})[event] = target
        return _dump({"initial": spec.children[""][0], "table": table})

    def from_yaml(self, text: str) -> Built:
        doc = _parse(text)
        return Built(FlatTable({s: dict(arcs) for s, arcs in doc["table"].items()}, doc["initial"]))


# --- transitions ---------------------------------------------------------------------------------


class Model:
    state: str


class Transitions:
    name = "transitions"
    dist = "transitions"

    def _states(self, spec: Spec, parent: str, counter: Counter) -> list[Any]:
        out: list[Any] = []
        for name in spec.children[parent]:
            state: dict[str, Any] = {"name": name}
            if spec.callbacks:
                state.update(on_enter=counter.enter, on_exit=counter.exit)
            if name in spec.children:
                state["children"] = self._states(spec, name, counter)
                state["initial"] = spec.children[name][0]
            out.append(state)
        return out

    def build(self, spec: Spec) -> Built:
        counter = Counter()
        path = "_".join  # transitions names a nested state by its path: P_P1_P1a
        arcs = [
            {"trigger": e, "source": path(spec.path(s)), "dest": path(spec.path(t))} for e, s, t in spec.arcs
        ]
        kind = self._hierarchical() if spec.callbacks else self._flat()
        model = Model()
        states = self._states(spec, "", counter)
        initial = spec.children[""][0]
        kind(model=model, states=states, transitions=arcs, initial=initial, auto_transitions=False)
        return Built(model, counter)

    @staticmethod
    def _flat() -> Any:
        from transitions import Machine

        return Machine

    @staticmethod
    def _hierarchical() -> Any:
        from transitions.extensions import HierarchicalMachine

        return HierarchicalMachine

    def stepper(self, built: Built, event: str) -> Step:
        return partial(built.machine.trigger, event)

    def leaf(self, built: Built) -> str:
        return str(built.machine.state).rsplit("_", 1)[-1]

    def chain_yaml(self, spec: Spec) -> str:
        arcs = [{"trigger": e, "source": s, "dest": t} for e, s, t in spec.arcs]
        return _dump({"states": spec.children[""], "transitions": arcs, "initial": spec.children[""][0]})

    def from_yaml(self, text: str) -> Built:
        model = Model()
        self._flat()(model=model, **_parse(text), auto_transitions=False)
        return Built(model)


# --- python-statemachine -------------------------------------------------------------------------


class PythonStatemachine:
    name = "python-statemachine"
    dist = "python-statemachine"

    def _states(self, spec: Spec, parent: str, counter: Counter) -> dict[str, Any]:
        out: dict[str, Any] = {}
        for i, name in enumerate(spec.children[parent]):
            state: dict[str, Any] = {"initial": True} if i == 0 else {}
            if spec.callbacks:
                state.update(enter=counter.enter, exit=counter.exit)
            if name in spec.children:
                state["states"] = self._states(spec, name, counter)
            arcs: dict[str, list[dict[str, str]]] = {}
            for event, source, target in spec.arcs:
                if source == name:
                    arcs.setdefault(event, []).append({"target": target})
            if arcs:
                state["on"] = arcs
            out[name] = state
        return out

    def build(self, spec: Spec) -> Built:
        counter = Counter()
        if spec == flat_spec():
            return Built(_toggle_class()())
        from statemachine.io import create_machine_class_from_definition

        cls = create_machine_class_from_definition("Bench", states=self._states(spec, "", counter))
        return Built(cls(), counter)

    def stepper(self, built: Built, event: str) -> Step:
        return partial(built.machine.send, event)

    def leaf(self, built: Built) -> str:
        return str(list(built.machine.configuration_values)[-1])

    def chain_yaml(self, spec: Spec) -> str:
        states: dict[str, Any] = {}
        for i, name in enumerate(spec.children[""]):
            states[name] = {"initial": True} if i == 0 else {}
        for event, source, target in spec.arcs:
            states[source].setdefault("transitions", []).append({"event": event, "target": target})
        return _dump({"name": "chain", "states": states})

    def from_yaml(self, text: str) -> Built:
        from statemachine.io import load

        return Built(load(text, format="yaml")())


def _toggle_class() -> Any:
    """W1 as a class declared in Python, the library's first idiom."""
    from statemachine import State, StateChart

    class Toggle(StateChart):  # type: ignore[type-arg]
        A = State(initial=True)
        B = State()
        toggle = A.to(B) | B.to(A)

    return Toggle


# --- sismic --------------------------------------------------------------------------------------


class Sismic:
    name = "sismic"
    dist = "sismic"

    def _state(self, spec: Spec, name: str) -> dict[str, Any]:
        state: dict[str, Any] = {"name": name}
        if spec.callbacks:
            state.update({"on entry": "entries += 1", "on exit": "exits += 1"})
        if name in spec.children:
            state["initial"] = spec.children[name][0]
            state["states"] = [self._state(spec, kid) for kid in spec.children[name]]
        arcs = [{"event": e, "target": t} for e, s, t in spec.arcs if s == name]
        if arcs:
            state["transitions"] = arcs
        return state

    def _document(self, spec: Spec) -> dict[str, Any]:
        rooted = Spec({**spec.children, "root": spec.children[""]}, spec.arcs, spec.callbacks)
        root = self._state(rooted, "root")
        return {"statechart": {"name": "bench", "root state": root}}

    def _start(self, statechart: Any) -> Built:
        from sismic.interpreter import Interpreter

        interpreter = Interpreter(statechart, initial_context={"entries": 0, "exits": 0})
        interpreter.execute_once()
        return Built(interpreter)

    def build(self, spec: Spec) -> Built:
        from sismic.io.datadict import import_from_dict

        return self._start(import_from_dict(self._document(spec)))

    def stepper(self, built: Built, event: str) -> Step:
        interpreter = built.machine
        queue, execute_once = interpreter.queue, interpreter.execute_once

        def step() -> None:
            queue(event)
            execute_once()

        return step

    def leaf(self, built: Built) -> str:
        return str(built.machine.configuration[-1])

    def counts(self, built: Built) -> tuple[int, int]:
        context = built.machine.context
        return int(context["entries"]), int(context["exits"])

    def chain_yaml(self, spec: Spec) -> str:
        return _dump(self._document(spec))

    def from_yaml(self, text: str) -> Built:
        from sismic.io import import_from_yaml

        return self._start(import_from_yaml(text))


ADAPTERS: dict[str, Adapter] = {
    "floor": Floor(),
    "transitions": Transitions(),
    "python-statemachine": PythonStatemachine(),
    "sismic": Sismic(),
}
IMPORTS = {
    "floor": "yaml",
    "transitions": "transitions",
    "python-statemachine": "statemachine",
    "sismic": "sismic",
}


def counts(adapter: Adapter, built: Built) -> tuple[int, int]:
    """Entries and exits counted by the callbacks (sismic keeps them in its context)."""
    if isinstance(adapter, Sismic):
        return adapter.counts(built)
    return built.counter.entries, built.counter.exits
