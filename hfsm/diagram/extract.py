"""Machines -> figures: one per machine (callees inline as clusters down to a depth), and the overview.

Node ids are state paths relative to the figure's machine (part.py); a state and an outcome of one
machine never share a name, so outcomes use the same scheme. Markers end in '@…', which no name can
contain.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, field

from hfsm.autonomy import LEVELS, join_key
from hfsm.checks.context import CheckContext
from hfsm.diagram import regions, text
from hfsm.diagram.model import Cluster, Edge, Figure, Item, Node, Ref, Role, Style
from hfsm.diagram.part import Part, cluster_id, node_id
from hfsm.graph import ANY, WATCH, Arc, arcs
from hfsm.load import Loaded
from hfsm.model import CallState, ChoiceState, Machine, ParallelState, state_calls
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec

START = "@start"
TIMER = "@timer"
ANY_NODE = "@any"
WATCH_NODE = "@watch"
BORDER = "cluster_@machine"  # the figure's own machine, when its watches leave from its border
OVERVIEW = "call-graph"
BARRIER = "barrier"
_STYLE: dict[str, Style] = {
    "outcome": "success",
    "choice": "success",
    "else": "success",
    "join": "success",
    "watch": "success",
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


class Builder:
    def __init__(self, src: Sources, links: Collection[str]) -> None:
        self.src = src
        self.links = links

    def part(self, name: str, rel: Ref, depth: int, border: str = "") -> Part:
        """`border`: the cluster this machine is drawn in (its watches leave from there)."""
        m = self.src.machines[name]
        inner: dict[str, Part] = {}
        for s, st in m.states.items():
            if depth > 0 and isinstance(st, CallState) and st.do in self.src.machines:
                inner[s] = self.part(st.do, (*rel, s), depth - 1, cluster_id((*rel, s)))
            elif depth > 0 and isinstance(st, ParallelState):
                inner[s] = regions.inline(self, st, (*rel, s), depth)
        outcomes = {o: node_id((*rel, o)) for o in m.all_outcomes}

        def entry(state: str) -> str:
            return inner[state].entry if state in inner else node_id((*rel, state))

        items: list[Item] = [self._state(m, s, rel, inner.get(s)) for s in m.states]
        edges = [e for sub in inner.values() for e in sub.edges]
        edges += self._edges(m, rel, inner, entry, outcomes)
        if m.watch:
            anchor = node_id(rel, WATCH_NODE)
            items.insert(0, Node(anchor, "point", "", ref=(*rel, WATCH)))
            edges += self._border_watches(m, rel, anchor, border or BORDER, entry, outcomes)
            if not border:
                items = [Cluster(BORDER, "", (), tuple(items), kind="machine")]
        items += [self._outcome(m, o, rel) for o in m.all_outcomes]
        if m.timer is not None:
            timer = node_id(rel, TIMER)
            shown = text.timer(m.timer, m.params)
            items.append(Node(timer, "timer", "", xlabel=shown, ref=(*rel, TIMER)))
            edges.append(
                Edge(timer, outcomes["timeout"], ("timeout",), "failure", (*rel, TIMER), ("timeout",))
            )
        if m.any:
            items.append(Node(node_id(rel, ANY_NODE), "any", "any state", ref=(*rel, ANY)))
        first = inner.get(m.initial_state)
        lhead = first.lhead if first else ""
        rows = tuple(row for sub in inner.values() for row in sub.rows)
        return Part(tuple(items), tuple(edges), outcomes, entry(m.initial_state), lhead, rows)

    def _state(self, m: Machine, s: str, rel: Ref, inner: Part | None) -> Item:
        st = m.states[s]
        ref = (*rel, s)
        if isinstance(st, ChoiceState):
            return Node(node_id(ref), "choice", s, ref=ref, tooltip=st.doc or "")
        timer = (f"timer {text.timer(st.timer, m.params)}",) if st.timer is not None else ()
        if st.scope is not None:
            timer = (text.scope(st.scope.name), *timer)
        if isinstance(st, ParallelState):
            if inner is not None:
                return regions.cluster(self, st, ref, inner, timer)
            return Node(
                node_id(ref),
                "parallel",
                s,
                timer,
                ref,
                tooltip=st.doc or "",
                lanes=regions.lanes(self, st, ref),
            )
        lines = text.call(st.do, st.with_) + timer
        link = st.do if st.do in self.links else ""
        if inner is not None:
            bottom = tuple(inner.outcomes.values())
            return Cluster(cluster_id(ref), s, lines, inner.items, bottom, ref, link, st.doc or "")
        return Node(node_id(ref), self.role(st.do), s, lines, ref, link=link, tooltip=st.doc or "")

    def role(self, do: str) -> Role:
        spec = self.src.specs.get(do)
        if spec is None or spec.kind == "primitive":
            return "primitive"
        if spec.kind == "builtin":
            return "barrier" if do == BARRIER else "builtin"
        return "machine"

    @staticmethod
    def _outcome(m: Machine, o: str, rel: Ref) -> Node:
        role: Role = "failure" if o in m.failure_outcomes else "success"
        return Node(node_id((*rel, o)), role, o, ref=(*rel, o))

    def _edges(
        self,
        m: Machine,
        rel: Ref,
        inner: Mapping[str, Part],
        entry: Callable[[str], str],
        outcomes: Mapping[str, str],
    ) -> list[Edge]:
        merged: dict[tuple[str, str, str, str, Ref], Edge] = {}
        retries: list[Edge] = []
        for arc in arcs(m, self.src.specs):
            if arc.source == WATCH:
                continue
            if arc.kind == "retry":
                retries += self._retry(m, arc, rel, inner, retries)
                continue
            tail, ltail = self._tail(arc, rel, inner)
            head = outcomes.get(arc.target) or entry(arc.target)
            lhead = "" if arc.target in outcomes or arc.target not in inner else inner[arc.target].lhead
            style = _STYLE[arc.kind]
            ref = (*rel, arc.source)
            level = _level(m, arc)
            label = f"{_label(arc)} ({level})" if level else _label(arc)
            key = (tail, head, style, ltail, ref)
            old = merged.get(key)
            labels, events = (
                ((*old.labels, label), (*old.events, arc.event)) if old else ((label,), (arc.event,))
            )
            if old is not None and old.level and (not level or LEVELS.index(old.level) > LEVELS.index(level)):
                level = old.level
            merged[key] = Edge(tail, head, labels, style, ref, events, ltail, lhead=lhead, level=level)
        return [*merged.values(), *retries]

    def _retry(
        self, m: Machine, arc: Arc, rel: Ref, inner: Mapping[str, Part], done: list[Edge]
    ) -> list[Edge]:
        """One self-loop per retrying state labelled with text.retry; inline, from the outcome retried."""
        st = m.states[arc.source]
        assert isinstance(st, CallState) and st.retry is not None
        ref = (*rel, arc.source)
        if any(e.ref == ref and e.events == ("retry",) for e in done):
            return []
        spec = self.src.specs.get(st.do)
        failures = spec.failures if spec else frozenset()
        style: Style = "failure" if any(o in failures or o == "error" for o in st.retry.on) else "success"
        label = text.retry(st.retry, m.params)
        part = inner.get(arc.source)
        if part is None:
            node = node_id(ref)
            return [Edge(node, node, (label,), style, ref, ("retry",))]
        tails = [part.outcomes[o] for o in st.retry.on if o in part.outcomes] or [part.entry]
        return [Edge(t, part.entry, (label,), style, ref, ("retry",), lhead=part.lhead) for t in tails[:1]]

    def _border_watches(
        self,
        m: Machine,
        rel: Ref,
        anchor: str,
        border: str,
        entry: Callable[[str], str],
        outcomes: Mapping[str, str],
    ) -> list[Edge]:
        out = []
        for arc in arcs(m, self.src.specs):
            if arc.source == WATCH:
                head = outcomes.get(arc.target) or entry(arc.target)
                out.append(Edge(anchor, head, (_label(arc),), "success", (*rel, WATCH), (arc.event,), border))
        return out

    @staticmethod
    def _tail(arc: Arc, rel: Ref, inner: Mapping[str, Part]) -> tuple[str, str]:
        if arc.source == ANY:
            return node_id(rel, ANY_NODE), ""
        part = inner.get(arc.source)
        if part is None:
            return node_id((*rel, arc.source)), ""
        if arc.kind not in ("message", "watch", "join") and arc.event in part.outcomes:
            return part.outcomes[arc.event], ""
        return part.entry, cluster_id((*rel, arc.source))


def _level(m: Machine, arc: Arc) -> str:
    """The autonomy level the arc needs, or ''."""
    state = m.states.get(arc.source)
    if not isinstance(state, CallState | ParallelState) or not state.autonomy:
        return ""
    key = join_key(arc.target) if arc.kind in ("join", "else") else arc.event
    return state.autonomy.get(key, "")


def _label(arc: Arc) -> str:
    if arc.kind == "choice":
        return text.condition(arc.order, arc.event)
    if arc.kind == "watch":
        return text.wrap(f"[{arc.event}]")
    return text.wrap(arc.event) if arc.kind == "join" else arc.event


def machine_figure(name: str, src: Sources, depth: int = 0, links: Collection[str] = ()) -> Figure:
    """The figure of one machine; callees that are machines drawn inline `depth` levels down."""
    m = src.machines[name]
    part = Builder(src, links).part(name, (), max(depth, 0))
    start = Node(START, "start", "start")
    edges = (Edge(START, part.entry, (), "start", lhead=part.lhead), *part.edges)
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
        rows=part.rows,
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
            for _, do in state_calls(s, st):
                spec = src.specs.get(do)
                if spec is None or spec.kind != "builtin":
                    calls.setdefault((name, do), []).append(s)
                    pending.append(do)
    items = tuple(_overview_node(n, src, links) for n in order)
    edges = tuple(
        Edge(a, b, (text.wrap(", ".join(dict.fromkeys(states)), text.LINE_WIDTH),), "call")
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
    lines = tuple(text.wrap(text.params(m.params), text.LINE_WIDTH).split("\n")) if m.params else ()
    return Node(name, "machine", name, lines, link=name if name in links else "", tooltip=m.doc or "")
