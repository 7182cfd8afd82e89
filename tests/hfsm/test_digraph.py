"""hfsm.digraph against networkx on random graphs: the same components, reach and path lengths."""

from __future__ import annotations

from itertools import pairwise

import networkx as nx
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm import digraph

EDGES = st.lists(st.tuples(st.integers(0, 9), st.integers(0, 9)), max_size=40)


def both(edges: list[tuple[int, int]]) -> tuple[digraph.MultiDiGraph, nx.MultiDiGraph]:
    ours, theirs = digraph.MultiDiGraph(), nx.MultiDiGraph()
    ours.add_nodes_from(range(10))
    theirs.add_nodes_from(range(10))
    for u, v in edges:
        ours.add_edge(u, v, w=u + v)
        theirs.add_edge(u, v, w=u + v)
    return ours, theirs


@settings(max_examples=200, deadline=None)
@given(EDGES)
def test_strongly_connected_components_agree(edges: list[tuple[int, int]]) -> None:
    ours, theirs = both(edges)
    found = sorted(sorted(c) for c in digraph.strongly_connected_components(ours))
    assert found == sorted(sorted(c) for c in nx.strongly_connected_components(theirs))


@settings(max_examples=200, deadline=None)
@given(EDGES, st.integers(0, 9), st.integers(0, 9))
def test_reach_and_shortest_paths_agree(edges: list[tuple[int, int]], a: int, b: int) -> None:
    ours, theirs = both(edges)
    assert digraph.descendants(ours, a) == nx.descendants(theirs, a)
    assert ours.in_degree(b) == theirs.in_degree(b)
    if nx.has_path(theirs, a, b):
        path = digraph.shortest_path(ours, a, b)
        assert len(path) == len(nx.shortest_path(theirs, a, b))
        assert path[0] == a and path[-1] == b and all(ours.has_edge(u, v) for u, v in pairwise(path))


def test_subgraphs_and_edge_views_keep_parallel_edges_and_attributes() -> None:
    g = digraph.MultiDiGraph()
    g.add_edge("a", "b", kind="x")
    g.add_edge("a", "b", kind="y")
    g.add_edge("b", "c", kind="x")
    assert g.in_degree("b") == 2 and g.edges["a", "b", 1] == {"kind": "y"}
    only_x = digraph.subgraph_view(g, filter_edge=lambda u, v, k: g.edges[u, v, k]["kind"] == "x")
    assert only_x.in_degree("b") == 1
    assert list(only_x.subgraph(["a", "b"])) == ["a", "b"] and not only_x.subgraph(["a", "b"]).has_edge("b", "c")


def test_a_digraph_keeps_one_edge_per_pair() -> None:
    g = digraph.DiGraph()
    g.add_edge("m", "n", states=["s"])
    g.edges["m", "n"]["states"].append("t")
    g.add_edge("m", "n")
    assert g.in_degree("n") == 1 and g.edges["m", "n"] == {"states": ["s", "t"]}
    assert list(g.predecessors("n")) == ["m"] and list(g.successors("m")) == ["n"]
