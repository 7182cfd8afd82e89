"""The diagram model: what a figure shows, as plain frozen values, with no drawing syntax in it.

Why: extraction (machines -> figures), the trace overlay and the renderers stay apart, as in
python-statemachine's `contrib/diagram`. A node says what it *is* (its role); a renderer decides how
that looks (dot.py maps roles to shapes).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, TypeAlias

Role = Literal[
    "machine",  # a call state whose callee is a machine: rounded box
    "primitive",  # a call state whose callee is a primitive: ellipse
    "builtin",  # a call state whose callee is a built-in behaviour: ellipse
    "choice",  # a choice state: diamond
    "parallel",  # a parallel state drawn whole: one box divided by dashed lines into its lanes
    "barrier",  # a state that calls `barrier`: a thick synchronisation bar (UML fork/join)
    "success",  # an outcome of the machine that is not a failure
    "failure",  # an outcome of the machine listed in its failures
    "timer",  # the machine's timer: solid black circle
    "start",  # the marker of the initial state
    "any",  # the source of the machine's `any:` arcs
    "note",  # plain text (legend)
    "point",  # an invisible anchor (legend; where the machine's watches leave its border)
]
Style = Literal[
    "success",  # a successful outcome of the callee, an ordinary event, a condition: solid
    "failure",  # a failure outcome of the callee, `timeout`, `error`: dashed
    "message",  # a message in `receives`: dotted and bold
    "start",  # from the start marker to the initial state
    "call",  # overview: a machine calls a behaviour
    "invisible",  # layout only (legend)
]
Ref: TypeAlias = tuple[str, ...]
"""A state's path relative to the figure's machine: ('lift',), ('lift', 'signal'); trace overlay key."""

Emphasis = Literal["normal", "faded", "ended"]
ClusterKind = Literal[
    "call",  # a state whose callee is drawn inline: rounded box
    "parallel",  # a parallel state drawn with its regions inside: rounded box
    "region",  # a region of a parallel state: dashed box
    "machine",  # the border of the figure's own machine, from which its watches leave: no label
]


@dataclass(frozen=True)
class Lane:
    """A region of a parallel state drawn whole (at depth 0): its name, its call, whether awaited."""

    title: str
    lines: tuple[str, ...]
    background: bool = False
    ref: Ref | None = None
    link: str = ""  # the figure of the region's machine
    barrier: bool = False  # the region calls `barrier`: a synchronisation bar over its name
    stats: tuple[str, ...] = ()
    emphasis: Emphasis = "normal"


@dataclass(frozen=True)
class Node:
    id: str
    role: Role
    title: str  # first line, bold
    lines: tuple[str, ...] = ()  # smaller lines under the title: what it calls, its timer
    ref: Ref | None = None
    xlabel: str = ""  # text beside the node (the timer's duration, where agents ended)
    link: str = ""  # a figure this node links to (a machine's name)
    tooltip: str = ""
    stats: tuple[str, ...] = ()  # overlay lines: visits and time
    emphasis: Emphasis = "normal"
    lanes: tuple[Lane, ...] = ()  # a parallel state's regions


@dataclass(frozen=True)
class Cluster:
    """A state whose callee is drawn inline (--depth), holding the callee's own nodes; or a parallel
    state holding its regions, a region, the border of the figure's machine."""

    id: str
    title: str
    lines: tuple[str, ...]
    items: tuple[Item, ...]
    bottom: tuple[str, ...] = ()  # node ids on one rank: the callee's outcomes
    ref: Ref | None = None
    link: str = ""
    tooltip: str = ""
    stats: tuple[str, ...] = ()
    emphasis: Emphasis = "normal"
    kind: ClusterKind = "call"


Item: TypeAlias = Node | Cluster


@dataclass(frozen=True)
class Edge:
    source: str  # a node id
    target: str  # a node id
    labels: tuple[str, ...]  # shown joined by " | "
    style: Style
    ref: Ref | None = None  # the path of the state whose events these are (ANY last for `any:`)
    events: tuple[str, ...] = ()  # the events merged into this arc, for the overlay
    ltail: str = ""  # a cluster id the arc leaves from its border
    lhead: str = ""  # a cluster id the arc ends at the border of
    count: int | None = None  # overlay: how often the arc was taken
    emphasis: Emphasis = "normal"
    level: str = ""  # the highest autonomy level an event of this arc needs: coloured


@dataclass(frozen=True)
class Figure:
    name: str  # the output file's stem
    title: str  # bold first line of the caption
    subtitle: str = ""  # the rest of the first line (parameters)
    caption: str = ""  # the machine's doc
    items: tuple[Item, ...] = ()
    edges: tuple[Edge, ...] = ()
    top: tuple[str, ...] = ()  # node ids on the top rank
    bottom: tuple[str, ...] = ()  # node ids on the bottom rank
    rows: tuple[tuple[str, ...], ...] = ()  # further groups of node ids on one rank each
    notes: tuple[str, ...] = ()  # lines under the caption (overlay summary)
    rankdir: Literal["TB", "LR"] = "TB"
    ranksep: float = 0.45  # inches between ranks


def walk(items: tuple[Item, ...]) -> list[Item]:
    """Every item, depth first, in declaration order."""
    out: list[Item] = []
    for item in items:
        out.append(item)
        if isinstance(item, Cluster):
            out.extend(walk(item.items))
    return out


def nodes(figure: Figure) -> list[Node]:
    return [i for i in walk(figure.items) if isinstance(i, Node)]
