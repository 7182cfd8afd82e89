"""Node ids, and one machine drawn at one place: shared by extract.py and regions.py.

Node ids are state paths relative to the figure's machine ('lift', 'lift/signal'); below a parallel
state the region's name comes next ('search/detect/look'), as in trace paths.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import dataclass
from typing import Protocol

from hfsm.diagram.model import Edge, Item, Ref, Role
from hfsm.model import Machine


def node_id(rel: Ref, leaf: str = "") -> str:
    return "/".join((*rel, leaf) if leaf else rel)


def cluster_id(rel: Ref) -> str:
    return "cluster_" + node_id(rel)


@dataclass(frozen=True)
class Part:
    """One machine drawn at one place: its items and arcs, its outcome nodes, where arcs enter it.

    `lhead`: the cluster at whose border arcs into this part end (a parallel state drawn inline);
    `rows`: groups of node ids on one rank each (the first states of a parallel state's regions).
    """

    items: tuple[Item, ...]
    edges: tuple[Edge, ...]
    outcomes: dict[str, str]
    entry: str
    lhead: str = ""
    rows: tuple[tuple[str, ...], ...] = ()


class Drawer(Protocol):
    """What regions.py asks of the figure's builder (extract.Builder): the machines it may draw inline,
    the callees that get a link, a callee's role, and a machine drawn at a place."""

    @property
    def links(self) -> Collection[str]: ...

    @property
    def machines(self) -> Mapping[str, Machine]: ...

    def role(self, do: str) -> Role: ...

    def part(self, name: str, rel: Ref, depth: int, border: str = "") -> Part: ...
