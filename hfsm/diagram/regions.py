"""A parallel state drawn as UML and SCXML draw orthogonal regions.

At depth 0 it is one node, a box divided by dashed lines into its lanes (region, call, `background`).
Drawn inline (--depth), it is a cluster of dashed region clusters, each holding its region's machine
(down to the depth left) or its one call; arcs enter and leave it at its border.
"""

from __future__ import annotations

from hfsm.diagram import text
from hfsm.diagram.model import Cluster, Edge, Item, Lane, Node, Ref
from hfsm.diagram.part import Drawer, Part, cluster_id, node_id
from hfsm.model import ParallelState, Region

BACKGROUND = "background"


def _call(region: Region) -> tuple[str, ...]:
    return text.call(region.do, region.with_) + ((BACKGROUND,) if region.background else ())


def lanes(b: Drawer, st: ParallelState, ref: Ref) -> tuple[Lane, ...]:
    return tuple(
        Lane(
            name,
            _call(r),
            r.background,
            (*ref, name),
            r.do if r.do in b.links else "",
            b.role(r.do) == "barrier",
        )
        for name, r in st.parallel.items()
    )


def inline(b: Drawer, st: ParallelState, ref: Ref, depth: int) -> Part:
    """The regions of a parallel state drawn inside its cluster, `depth` levels down."""
    items: list[Item] = []
    edges: list[Edge] = []
    entries: list[str] = []
    rows: list[tuple[str, ...]] = []
    for name, r in st.parallel.items():
        rref = (*ref, name)
        link = r.do if r.do in b.links else ""
        if r.do in b.machines:
            part = b.part(r.do, rref, depth - 1, cluster_id(rref))
            bottom = tuple(part.outcomes.values())
            items.append(
                Cluster(
                    cluster_id(rref),
                    name,
                    _call(r),
                    part.items,
                    bottom,
                    rref,
                    link,
                    r.doc or "",
                    kind="region",
                )
            )
            edges += part.edges
            rows += part.rows
            entries.append(part.entry)
        else:
            node = Node(node_id(rref), b.role(r.do), name, _call(r), rref, link=link, tooltip=r.doc or "")
            items.append(Cluster(cluster_id(rref), "", (), (node,), kind="region"))
            entries.append(node.id)
    rows.insert(0, tuple(entries))  # the regions side by side, as UML draws them
    return Part(tuple(items), tuple(edges), {}, entries[0], cluster_id(ref), tuple(rows))


def cluster(b: Drawer, st: ParallelState, ref: Ref, inner: Part, timer: tuple[str, ...]) -> Cluster:
    return Cluster(cluster_id(ref), ref[-1], timer, inner.items, (), ref, "", st.doc or "", kind="parallel")
