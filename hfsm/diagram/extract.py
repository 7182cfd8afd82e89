"""Machines -> figures: one per machine (callees inline as clusters down to a depth), and the overview.

Node ids are state paths relative to the figure's machine ('lift', 'lift/signal'); a state and an
outcome of one machine never share a name, so outcomes use the same scheme. Markers end in '@…',
which no name can contain.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, field

from hfsm.checks.context import CheckContext
from hfsm.diagram import text
from hfsm.diagram.model import Cluster, Edge, Figure, Item, Node, Ref, Role, Style
from hfsm.graph import ANY, Arc, arcs
from hfsm.load import Loaded
from hfsm.model import CallState, Machine
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec

START = "@start"
TIMER = "@timer"
ANY_NODE = "@any"
OVERVIEW = "call-graph"
_STYLE: dict[str, Style] = {
    "outcome": "success",
    "choice": "success",
    "else": "success",
    "failure": "failure",
    "timeout": "failure",
    "error": "failure",
    "message": "message",
}


@dataclass(frozen=True)
class Sources:
    """The machines that may be drawn, and the signature of every behaviour they call."""

    machines: Mapping[str, Machine]
    specs: Mapping[str, BehaviourSpec]
    docs: Mapping[str, str] = field(default_factory=dict)

    @classmethod
    def from_loaded(cls, loaded: Loaded, registry: Registry) -> Sources:
        machines = {name: mf.model for name, mf in loaded.machines.items()}
        return cls(machines, CheckContext(loaded.machines, registry).specs)


def node_id(rel: Ref, leaf: str = "") -> str:
    return "/".join((*rel, leaf) if leaf else rel)


def cluster_id(rel: Ref) -> str:
    return "cluster_" + node_id(rel)


@dataclass(frozen=True)
class _Part:
    """One machine drawn at one place: its items and arcs, its outcome nodes, where arcs enter it."""

    items: tuple[Item, ...]
    edges: tuple[Edge, ...]
    outcomes: dict[str, str]
    entry: str


class _Builder:
    def __init__(self, src: Sources, links: Collection[str]) -> None:
        self.src = src
        self.links = links

    def part(self, name: str, rel: Ref, depth: int) -> _Part:
        m = self.src.machines[name]
        inner = {
            s: self.part(st.do, (*rel, s), depth - 1)
            for s, st in m.states.items()
            if depth > 0 and isinstance(st, CallState) and st.do in self.src.machines
        }
        outcomes = {o: node_id((*rel, o)) for o in m.all_outcomes}

        def entry(state: str) -> str:
            return inner[state].entry if state in inner else node_id((*rel, state))

        items: list[Item] = [self._state(m, s, rel, inner.get(s)) for s in m.states]
        items += [self._outcome(m, o, rel) for o in m.all_outcomes]
        edges = [e for sub in inner.values() for e in sub.edges]
        edges += self._edges(m, rel, inner, entry, outcomes)
        if m.timer is not None:
            timer = node_id(rel, TIMER)
            items.append(Node(timer, "timer", "", xlabel=text.timer(m.timer), ref=(*rel, TIMER)))
            edges.append(
                Edge(timer, outcomes["timeout"], ("timeout",), "failure", (*rel, TIMER), ("timeout",))
            )
        if m.any:
            items.append(Node(node_id(rel, ANY_NODE), "any", "any state", ref=(*rel, ANY)))
        return _Part(tuple(items), tuple(edges), outcomes, entry(m.initial_state))

    def _state(self, m: Machine, s: str, rel: Ref, inner: _Part | None) -> Item:
        st = m.states[s]
        ref = (*rel, s)
        if not isinstance(st, CallState):
            return Node(node_id(ref), "choice", s, ref=ref, tooltip=st.doc or "")
        lines = text.call(st.do, st.with_)
        if st.timer is not None:
            lines += (f"timer {text.timer(st.timer)}",)
        link = st.do if st.do in self.links else ""
        if inner is not None:
            bottom = tuple(inner.outcomes.values())
            return Cluster(cluster_id(ref), s, lines, inner.items, bottom, ref, link, st.doc or "")
        return Node(node_id(ref), self._role(st.do), s, lines, ref, link=link, tooltip=st.doc or "")

    def _role(self, do: str) -> Role:
        spec = self.src.specs.get(do)
        if spec is None or spec.kind == "primitive":
            return "primitive"
        return "builtin" if spec.kind == "builtin" else "machine"

    @staticmethod
    def _outcome(m: Machine, o: str, rel: Ref) -> Node:
        role: Role = "failure" if o in m.failure_outcomes else "success"
        return Node(node_id((*rel, o)), role, o, ref=(*rel, o))

    def _edges(
        self,
        m: Machine,
        rel: Ref,
        inner: Mapping[str, _Part],
        entry: Callable[[str], str],
        outcomes: Mapping[str, str],
    ) -> list[Edge]:
        merged: dict[tuple[str, str, str, str, Ref], Edge] = {}
        for arc in arcs(m, self.src.specs):
            tail, ltail = self._tail(arc, rel, inner)
            head = outcomes.get(arc.target) or entry(arc.target)
            style = _STYLE[arc.kind]
            ref = (*rel, arc.source)
            label = text.condition(arc.order, arc.event) if arc.kind == "choice" else arc.event
            key = (tail, head, style, ltail, ref)
            old = merged.get(key)
            if old is None:
                merged[key] = Edge(tail, head, (label,), style, ref, (arc.event,), ltail)
            else:
                merged[key] = Edge(
                    tail, head, (*old.labels, label), style, ref, (*old.events, arc.event), ltail
                )
        return list(merged.values())

    @staticmethod
    def _tail(arc: Arc, rel: Ref, inner: Mapping[str, _Part]) -> tuple[str, str]:
        if arc.source == ANY:
            return node_id(rel, ANY_NODE), ""
        part = inner.get(arc.source)
        if part is None:
            return node_id((*rel, arc.source)), ""
        if arc.kind != "message" and arc.event in part.outcomes:
            return part.outcomes[arc.event], ""
        return part.entry, cluster_id((*rel, arc.source))


def machine_figure(name: str, src: Sources, depth: int = 0, links: Collection[str] = ()) -> Figure:
    """The figure of one machine; callees that are machines drawn inline `depth` levels down."""
    m = src.machines[name]
    part = _Builder(src, links).part(name, (), max(depth, 0))
    start = Node(START, "start", "start")
    edges = (Edge(START, part.entry, (), "start"), *part.edges)
    top = tuple(i for i in (START, TIMER, ANY_NODE) if i == START or _has(part.items, i))
    return Figure(
        name=name,
        title=name,
        subtitle=text.params(m.params),
        caption=m.doc or "",
        items=(start, *part.items),
        edges=edges,
        top=top,
        bottom=tuple(part.outcomes.values()),
    )


def _has(items: Sequence[Item], node: str) -> bool:
    return any(isinstance(i, Node) and i.id == node for i in items)


def overview(src: Sources, roots: Sequence[str], links: Collection[str] = ()) -> Figure:
    """Who calls whom: machines as rounded boxes, primitives as ellipses; built-ins left out."""
    order: list[str] = []
    calls: dict[tuple[str, str], list[str]] = {}
    pending = list(roots)
    while pending:
        name = pending.pop(0)
        if name in order:
            continue
        order.append(name)
        m = src.machines.get(name)
        for s, st in m.states.items() if m else ():
            spec = src.specs.get(st.do) if isinstance(st, CallState) else None
            if isinstance(st, CallState) and (spec is None or spec.kind != "builtin"):
                calls.setdefault((name, st.do), []).append(s)
                pending.append(st.do)
    items = tuple(_overview_node(n, src, links) for n in order)
    edges = tuple(
        Edge(a, b, (text.shorten(", ".join(states), text.LINE_WIDTH),), "call")
        for (a, b), states in calls.items()
    )
    return Figure(
        OVERVIEW,
        "call graph",
        caption="Who calls whom: each arc is labelled with the calling states.",
        items=items,
        edges=edges,
    )


def _overview_node(name: str, src: Sources, links: Collection[str]) -> Node:
    m = src.machines.get(name)
    if m is None:
        return Node(name, "primitive", name)
    lines = (text.shorten(text.params(m.params), text.LINE_WIDTH),) if m.params else ()
    return Node(name, "machine", name, lines, link=name if name in links else "", tooltip=m.doc or "")
