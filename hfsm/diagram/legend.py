"""The legend: every mark of the convention, drawn by the same renderer as the figures, with its meaning."""

from __future__ import annotations

import itertools

from hfsm.diagram.model import Edge, Figure, Item, Lane, Node, Style
from hfsm.diagram.text import TIMES

LEGEND = "legend"

_NODES: tuple[tuple[Node, str], ...] = (
    (
        Node("machine", "machine", "state", ("machine(arg=1)",)),
        "a state that calls a machine (rounded box; name, then the call with short arguments); "
        "in SVG it links to that machine's figure",
    ),
    (
        Node("primitive", "primitive", "state", ('primitive(arg="a")',)),
        "a state that calls a primitive or a built-in behaviour (ellipse)",
    ),
    (
        Node("choice", "choice", "state"),
        "a choice state (diamond): its arcs carry the conditions, tried in order 1:, 2:, … then else",
    ),
    (
        Node(
            "parallel",
            "parallel",
            "state",
            ("timer 30 s",),
            lanes=(
                Lane("a", ("primitive()",)),
                Lane("b", ("machine()",)),
                Lane("c", ("wait()", "background")),
            ),
        ),
        "a parallel state: its regions a, b, c run at once, divided by dashed lines, each with its call; "
        "a background region is never awaited; with --depth, each region is a dashed box holding its machine",
    ),
    (
        Node("barrier", "barrier", "state", ('barrier(name="lift")',)),
        "a state that calls barrier: a synchronisation bar (UML's fork and join): agents leave it together",
    ),
    (
        Node("timed", "builtin", "state", ('wait_for(message="go")', "timer 5 s")),
        "a state with its own timer: the duration in its label, its 'timeout' arc dashed",
    ),
    (
        Node("scoped", "machine", "state", ("machine()", "scope: pair_\u2026")),
        "a state whose behaviour runs under a scope, a team within the team: its messages and "
        "barriers are private to the scope's agents (a literal name is shown whole; one given by an "
        "expression by the text it starts with)",
    ),
    (Node("start", "start", "start"), "marks the initial state: the arc from it points there"),
    (
        Node("timer", "timer", "", xlabel="60 s"),
        "the timer of the whole machine (as in the paper's Figure 3): its 'timeout' arc ends the "
        "machine, whatever runs below",
    ),
    (
        Node("any", "any", "any state"),
        "the machine's any: arcs, shared by every state; a state's own arc for the same event wins",
    ),
    (Node("success", "success", "done"), "an outcome of the machine, a success (bottom row)"),
    (Node("failure", "failure", "failure"), "an outcome of the machine listed in its failures (bottom row)"),
)
_EDGES: tuple[tuple[str, Style, str], ...] = (
    ("done", "success", "solid: a successful outcome of the callee, an ordinary event, a condition"),
    ("failure", "failure", "dashed: a failure outcome of the callee, 'timeout', 'error'"),
    ("message", "message", "dotted, bold: a message in 'receives'; it preempts the callee"),
    (
        "a=done, b=x|y",
        "success",
        "a join rule of a parallel state: each region named ended in its outcome (b in x or in y); "
        "'else': every awaited region ended and no rule held",
    ),
    (
        "[vars.n > 3]",
        "success",
        "a watch: its condition in brackets, tried on entry and every tick; the machine's own watches "
        "leave from the border of its states",
    ),
)
_OVERLAY = (
    f"with --trace: '{TIMES}n' counts visits of a state (with the time spent in it) and of an arc; "
    "grey: never visited or taken; filled, bold: where an agent ended"
)


def legend() -> Figure:
    """A column of samples, each with its meaning to its right."""
    items: list[Item] = []
    edges: list[Edge] = []
    rows: list[tuple[str, ...]] = []
    firsts: list[str] = []
    for node, meaning in _NODES:
        note = Node(f"{node.id}@note", "note", meaning)
        items += [node, note]
        rows.append((node.id, note.id))
        firsts.append(node.id)
    for label, style, meaning in _EDGES:
        items += _arc_row(label, style, meaning, edges, rows, firsts)
    held = (
        "coloured, its level in parentheses: an arc that needs that autonomy level; below it the arc "
        "is held until the operator answers (autonomy:)"
    )
    items += _arc_row("failed (high)", "failure", held, edges, rows, firsts)
    edges[-1] = Edge(edges[-1].source, edges[-1].target, edges[-1].labels, "failure", level="high")
    retried = Node("retried", "primitive", "state", ("navigate()",))
    note = Node(
        "retried@note",
        "note",
        f"a retry: the call is made again, up to {TIMES}N more times, when it ends in one of these outcomes",
    )
    items += [retried, note]
    edges.append(Edge("retried", "retried", (f"retry {TIMES}3: failed",), "failure"))
    rows.append(("retried", note.id))
    firsts.append("retried")
    visited = Node(
        "visited",
        "primitive",
        "state",
        ("walk(metres=1)",),
        stats=(f"{TIMES}3, 12.5 s", "end: a"),
        emphasis="ended",
    )
    faded = Node("unvisited", "primitive", "state", ("walk(metres=2)",), emphasis="faded")
    note = Node("overlay@note", "note", _OVERLAY)
    items += [visited, faded, note]
    edges.append(Edge("visited", "unvisited", ("done",), "success", count=3))
    rows.append(("visited", "unvisited", note.id))
    firsts.append("visited")
    edges += [Edge(a, b, (), "invisible") for a, b in itertools.pairwise(firsts)]
    return Figure(
        name=LEGEND,
        title="hfsm-graph legend",
        caption="Vertices are states, arcs are labelled with the events that take them.",
        items=tuple(items),
        edges=tuple(edges),
        rows=tuple(rows),
        ranksep=0.15,
    )


def _arc_row(
    label: str, style: Style, meaning: str, edges: list[Edge], rows: list[tuple[str, ...]], firsts: list[str]
) -> list[Item]:
    a, b, note = f"arc_{label}@a", f"arc_{label}@b", Node(f"arc_{label}@note", "note", meaning)
    edges.append(Edge(a, b, (label,), style))
    rows.append((a, b, note.id))
    firsts.append(a)
    return [Node(a, "point", ""), Node(b, "point", ""), note]
