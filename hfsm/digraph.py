"""Small directed graphs for the checks: the part of networkx's API they use, without its import cost.

networkx takes longer to import than the rest of `hfsm-run --check` together; the checks need a
few hundred nodes at most, and five algorithms. Node and edge order is insertion order, as in
networkx, so findings come out in the same order.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from typing import Any

Node = Any  # hashable: a name, or a (kind, name) pair
Attrs = dict[str, Any]


class MultiDiGraph:
    """Directed graph with parallel edges; `edges[u, v, key]` is an edge's attribute dict."""

    multi = True

    def __init__(self) -> None:
        self.nodes: dict[Node, Attrs] = {}
        self._succ: dict[Node, dict[Node, dict[int, Attrs]]] = {}
        self._pred: dict[Node, dict[Node, dict[int, Attrs]]] = {}
        self.edges = _EdgeView(self)

    def add_node(self, node: Node, **attrs: Any) -> None:
        if node not in self.nodes:
            self.nodes[node] = {}
            self._succ[node] = {}
            self._pred[node] = {}
        self.nodes[node].update(attrs)

    def add_nodes_from(self, nodes: Iterable[Node], **attrs: Any) -> None:
        for node in nodes:
            self.add_node(node, **attrs)

    def add_edge(self, u: Node, v: Node, **attrs: Any) -> int:
        self.add_node(u)
        self.add_node(v)
        keyed = self._succ[u].setdefault(v, {})
        if not self.multi and keyed:
            keyed[0].update(attrs)
            return 0
        key = len(keyed)
        keyed[key] = dict(attrs)
        self._pred[v].setdefault(u, {})[key] = keyed[key]
        return key

    def __contains__(self, node: object) -> bool:
        return node in self.nodes

    def __iter__(self) -> Iterator[Node]:
        return iter(self.nodes)

    def __len__(self) -> int:
        return len(self.nodes)

    def has_edge(self, u: Node, v: Node) -> bool:
        return u in self._succ and v in self._succ[u]

    def successors(self, node: Node) -> Iterator[Node]:
        return iter(self._succ[node])

    def predecessors(self, node: Node) -> Iterator[Node]:
        return iter(self._pred[node])

    def in_degree(self, node: Node) -> int:
        return sum(len(keyed) for keyed in self._pred[node].values())

    def edge_items(self) -> Iterator[tuple[Node, Node, int, Attrs]]:
        for u, targets in self._succ.items():
            for v, keyed in targets.items():
                for key, attrs in keyed.items():
                    yield u, v, key, attrs

    def subgraph(self, nodes: Iterable[Node]) -> MultiDiGraph:
        """The graph induced by `nodes` (a copy sharing the attribute dicts)."""
        kept = set(nodes)
        g = type(self)()
        for node, attrs in self.nodes.items():
            if node in kept:
                g.add_node(node, **attrs)
        for u, v, key, attrs in self.edge_items():
            if u in kept and v in kept:
                g._put(u, v, key, attrs)
        return g

    def _put(self, u: Node, v: Node, key: int, attrs: Attrs) -> None:
        self._succ[u].setdefault(v, {})[key] = attrs
        self._pred[v].setdefault(u, {})[key] = attrs


class DiGraph(MultiDiGraph):
    """At most one edge from u to v; `edges[u, v]` is its attribute dict."""

    multi = False


class _EdgeView:
    def __init__(self, g: MultiDiGraph) -> None:
        self._g = g

    def __getitem__(self, edge: tuple[Node, Node] | tuple[Node, Node, int]) -> Attrs:
        u, v, *key = edge
        return self._g._succ[u][v][key[0] if key else 0]

    def __iter__(self) -> Iterator[tuple[Node, Node]]:
        return ((u, v) for u, targets in self._g._succ.items() for v in targets)


def subgraph_view(g: MultiDiGraph, filter_edge: Callable[[Node, Node, int], bool]) -> MultiDiGraph:
    """A copy of `g` with only the edges `filter_edge(u, v, key)` keeps."""
    kept = type(g)()
    for node, attrs in g.nodes.items():
        kept.add_node(node, **attrs)
    for u, v, key, attrs in g.edge_items():
        if filter_edge(u, v, key):
            kept._put(u, v, key, attrs)
    return kept


def descendants(g: MultiDiGraph, source: Node) -> set[Node]:
    """Every node reachable from `source` but `source` itself (as networkx)."""
    seen = {source}
    todo = [source]
    while todo:
        for nxt in g.successors(todo.pop()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen - {source}


def shortest_path(g: MultiDiGraph, source: Node, target: Node) -> list[Node]:
    """The fewest-edges path from source to target (breadth first, successors in insertion order)."""
    parent: dict[Node, Node | None] = {source: None}
    frontier = [source]
    while frontier and target not in parent:
        nxt_frontier = []
        for node in frontier:
            for nxt in g.successors(node):
                if nxt not in parent:
                    parent[nxt] = node
                    nxt_frontier.append(nxt)
        frontier = nxt_frontier
    if target not in parent:
        raise ValueError(f"no path from {source!r} to {target!r}")
    path = [target]
    while (up := parent[path[-1]]) is not None:
        path.append(up)
    return path[::-1]


_DONE = object()


def strongly_connected_components(g: MultiDiGraph) -> Iterator[set[Node]]:
    """Tarjan's algorithm, iterative (no recursion limit on long chains)."""
    index: dict[Node, int] = {}
    low: dict[Node, int] = {}
    stack: list[Node] = []
    on_stack: set[Node] = set()
    for root in g:
        if root in index:
            continue
        work: list[tuple[Node, Iterator[Node]]] = [(root, g.successors(root))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, _DONE)
            if child is not _DONE and child not in index:
                index[child] = low[child] = len(index)
                stack.append(child)
                on_stack.add(child)
                work.append((child, g.successors(child)))
                continue
            if child is not _DONE:
                if child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = set()
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.add(member)
                    if member == node:
                        break
                yield component
