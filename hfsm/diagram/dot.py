"""Figure -> DOT text, deterministically: declaration order, attributes sorted, no renderer involved.

The look ("paper" style, monochrome, print-safe) lives here: the role of a node picks its shape, the
style of an arc its line.
"""

from __future__ import annotations

import html
import textwrap
from collections.abc import Iterator, Mapping, Sequence

from hfsm.diagram.model import Cluster, ClusterKind, Edge, Emphasis, Figure, Item, Lane, Node, Role, Style
from hfsm.diagram.text import TIMES, labels, paragraph

FONT = "Helvetica"
FADED = "gray60"
NOTE_WIDTH = 80  # characters of a legend line
CAPTION_WIDTH, CAPTION_LINES = 90, 5  # a figure shows the sentences of its doc that fit in these
GRAPH = {
    "compound": "true",
    "fontname": FONT,
    "fontsize": "12",
    "forcelabels": "true",
    "labelloc": "t",
    "newrank": "true",
    "nodesep": "0.35",
}
NODE = {"fontname": FONT, "fontsize": "11", "margin": "0.12,0.05"}
EDGE = {"arrowsize": "0.7", "fontname": FONT, "fontsize": "9"}
ROLE: dict[Role, dict[str, str]] = {
    "machine": {"shape": "box", "style": "rounded"},
    "primitive": {"shape": "ellipse"},
    "builtin": {"shape": "ellipse"},
    "choice": {"shape": "diamond", "fontsize": "10", "margin": "0.03"},
    "parallel": {"shape": "box", "style": "rounded", "margin": "0.04"},
    "barrier": {"shape": "plaintext", "margin": "0"},
    "success": {"shape": "box", "peripheries": "2", "fontsize": "10"},
    "failure": {"shape": "doubleoctagon", "fontsize": "10"},
    "timer": {
        "shape": "circle",
        "style": "filled",
        "fillcolor": "black",
        "width": "0.22",
        "fixedsize": "true",
    },
    "start": {"shape": "plaintext", "fontsize": "9"},
    "any": {"shape": "plaintext", "fontsize": "9"},
    "note": {"shape": "plaintext", "fontsize": "10", "fixedsize": "true", "width": "5.6", "height": "0.5"},
    "point": {"shape": "point", "style": "invis", "width": "0.01"},
}
STYLE: dict[Style, dict[str, str]] = {
    "success": {"style": "solid"},
    "failure": {"style": "dashed"},
    "message": {"style": "dotted", "penwidth": "2"},
    "start": {"style": "solid"},
    "call": {"style": "solid"},
    "invisible": {"style": "invis"},
}
CLUSTER: dict[ClusterKind, str] = {
    "call": "rounded",
    "parallel": "rounded",
    "region": "dashed",
    "machine": "rounded",
}
BAR_WIDTH = 110  # points: the synchronisation bar of a `barrier`
LABEL_NODE = "@label"  # after a node's id: the plain-text node beside it that shows its xlabel


def to_dot(figure: Figure, link_ext: str = "svg") -> str:
    """The DOT text of a figure; node links point to `<machine>.<link_ext>`."""
    out = [f"digraph {_q(figure.name)} {{"]
    graph = {**GRAPH, "label": _caption(figure), "rankdir": figure.rankdir, "ranksep": f"{figure.ranksep:g}"}
    out += [f"  graph {_attrs(graph)};", f"  node {_attrs(NODE)};", f"  edge {_attrs(EDGE)};"]
    out += _items(figure.items, link_ext, "  ")
    for rank, ids in (("min", figure.top), ("max", figure.bottom), *(("same", r) for r in figure.rows)):
        if ids:
            out.append(_rank(rank, ids, "  "))
    out += [f"  {_q(e.source)} -> {_q(e.target)} {_attrs(_edge(e))};" for e in figure.edges]
    out.append("}")
    return "\n".join(out) + "\n"


def _items(items: Sequence[Item], link_ext: str, indent: str) -> Iterator[str]:
    for item in items:
        if isinstance(item, Node):
            yield f"{indent}{_q(item.id)} {_attrs(_node(item, link_ext))};"
            if item.xlabel:
                yield from _beside(item, indent)
        else:
            yield from _cluster(item, link_ext, indent)


def _beside(n: Node, indent: str) -> Iterator[str]:
    """A node's xlabel as a plain-text node to its right: laid out as a node, it never overlaps."""
    label = n.id + LABEL_NODE
    attrs = {"label": n.xlabel, "shape": "plaintext", "fontsize": "9", "margin": "0.02", "height": "0.2"}
    attrs.update(_emphasis("faded", "") if n.emphasis == "faded" else {})
    yield f"{indent}{_q(label)} {_attrs(attrs)};"
    yield f"{indent}{_q(n.id)} -> {_q(label)} {_attrs({'style': 'invis', 'minlen': '0'})};"
    yield _rank("same", (n.id, label), indent)


def _cluster(c: Cluster, link_ext: str, indent: str) -> Iterator[str]:
    yield f"{indent}subgraph {_q(c.id)} {{"
    style = CLUSTER[c.kind]
    label = _label(c.title, c.lines, c.stats) if c.title or c.stats else ""  # else the graph's caption
    attrs = {"label": label, "style": style, **_links(c.link, c.tooltip, link_ext)}
    attrs.update({"penwidth": "2.5"} if c.emphasis == "ended" else _emphasis(c.emphasis, style))
    yield f"{indent}  graph {_attrs(attrs)};"
    yield from _items(c.items, link_ext, indent + "  ")
    if c.bottom:
        yield _rank("same", c.bottom, indent + "  ")
    yield f"{indent}}}"


def _node(n: Node, link_ext: str) -> dict[str, str]:
    attrs = dict(ROLE[n.role])
    attrs["label"] = _node_label(n, link_ext)
    attrs.update(_links(n.link, n.tooltip, link_ext))
    attrs.update(_emphasis(n.emphasis, attrs.get("style", "")))
    return attrs


def _node_label(n: Node, link_ext: str) -> str:
    if n.role in ("timer", "point"):
        return ""
    if n.role == "any":
        return Html(f"<i>{_h(n.title)}</i>")
    if n.role == "note":
        return Raw("".join(_escape(line) + "\\l" for line in textwrap.wrap(n.title, NOTE_WIDTH)))
    if n.role in ("success", "failure", "start") and not n.lines and not n.stats:
        return n.title
    if n.role == "parallel":
        return _parallel(n, link_ext)
    if n.role == "barrier":
        return _barrier(n)
    return _label(n.title, n.lines, n.stats)


def _barrier(n: Node) -> str:
    """A thick bar (UML's fork and join) over the state's name and call: arcs arrive at the bar."""
    return Html(_barrier_table(_label(n.title, n.lines, n.stats)))


def _barrier_table(label: str) -> str:
    bar = f'<tr><td bgcolor="black" height="5" width="{BAR_WIDTH}" fixedsize="true"></td></tr>'
    return f'<table border="0" cellspacing="0" cellpadding="2">{bar}<tr><td>{label}</td></tr></table>'


def _parallel(n: Node, link_ext: str) -> str:
    """One box: the state's name (and timer) over its lanes, divided by dashed lines."""
    head = f'<tr><td colspan="{len(n.lanes)}">{_label(n.title, n.lines, n.stats)}</td></tr>'
    cells = "".join(_lane(lane, i == 0, link_ext) for i, lane in enumerate(n.lanes))
    return Html(
        f'<table border="0" cellborder="0" cellspacing="0" cellpadding="4">{head}<tr>{cells}</tr></table>'
    )


def _lane(lane: Lane, first: bool, link_ext: str) -> str:
    sides = "T" if first else "TL"
    href = f' href="{_h(lane.link)}.{link_ext}" title="{_h(lane.link)}"' if lane.link else ""
    label = _label(lane.title, lane.lines, lane.stats)
    if lane.barrier:
        label = _barrier_table(label)
    if lane.emphasis == "faded":
        label = f'<font color="{FADED}">{label}</font>'
    return f'<td border="1" style="dashed" sides="{sides}"{href}>{label}</td>'


def _label(title: str, lines: Sequence[str], stats: Sequence[str]) -> str:
    parts = [f"<b>{_h(title)}</b>"]
    parts += [f'<font point-size="9"><i>{_h(line)}</i></font>' for line in lines]
    parts += [f'<font point-size="9">{_h(line)}</font>' for line in stats]
    return Html("<br/>".join(parts))


def _links(link: str, tooltip: str, link_ext: str) -> dict[str, str]:
    """A link's tooltip is the state's doc, else the machine linked (never the label's HTML)."""
    attrs = {"tooltip": tooltip or link} if tooltip or link else {}
    if link:
        attrs["href"] = f"{link}.{link_ext}"
    return attrs


def _emphasis(emphasis: Emphasis, style: str) -> dict[str, str]:
    if emphasis == "faded":
        return {"color": FADED, "fontcolor": FADED}
    if emphasis == "ended":
        styles = [s for s in style.split(",") if s and s != "filled"]
        return {"fillcolor": "gray88", "penwidth": "2.5", "style": ",".join([*styles, "filled"])}
    return {}


# An arc held for the operator below its level, as FlexBE's editor colours them: the one
# colour in a monochrome figure, darker for the levels that ask a person more often.
LEVEL_COLOURS = {"off": "#2b8a3e", "low": "#1864ab", "high": "#c2410c", "full": "#b91c1c"}


def _edge(e: Edge) -> dict[str, str]:
    attrs = dict(STYLE[e.style])
    label = labels(e.labels)
    if e.count is not None:
        label = f"{label} {TIMES}{e.count}" if label else f"{TIMES}{e.count}"
        width = max(min(1.0 + e.count.bit_length() * 0.5, 4.0), float(attrs.get("penwidth", 1)))
        attrs["penwidth"] = f"{width:g}"
    if label:
        attrs["label"] = label
    if e.ltail:
        attrs["ltail"] = e.ltail
    if e.lhead:
        attrs["lhead"] = e.lhead
    if e.level:
        attrs.update({"color": LEVEL_COLOURS[e.level], "fontcolor": LEVEL_COLOURS[e.level]})
    if e.emphasis == "faded":
        attrs.update({"color": FADED, "fontcolor": FADED})
    return attrs


def _caption(figure: Figure) -> str:
    head = f"<b>{_h(figure.title)}</b>{_h(figure.subtitle)}"
    lines = [head]
    lines += [f'<font point-size="10">{_h(line)}</font>' for line in _wrap(figure.caption)]
    lines += [f'<font point-size="10"><i>{_h(line)}</i></font>' for line in figure.notes]
    return Html("<br/>".join(lines))


def _wrap(caption: str) -> tuple[str, ...]:
    return paragraph(caption, CAPTION_WIDTH, CAPTION_LINES) if caption else ()


def _rank(rank: str, ids: Sequence[str], indent: str) -> str:
    return f"{indent}{{rank={rank}; " + " ".join(f"{_q(i)};" for i in ids) + "}"


def _attrs(attrs: Mapping[str, str]) -> str:
    return "[" + ", ".join(f"{k}={_v(attrs[k])}" for k in sorted(attrs)) + "]"


class Html(str):
    """An HTML-like label, escaped already: written as `<…>`, not quoted."""

    __slots__ = ()


class Raw(str):
    """A quoted string whose escapes (`\\l`) are written as they are."""

    __slots__ = ()


def _v(value: str) -> str:
    if isinstance(value, Html):
        return f"<{value}>"
    return f'"{value}"' if isinstance(value, Raw) else _q(value)


def _q(text: str) -> str:
    return f'"{_escape(text)}"'


def _escape(text: str) -> str:
    return text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")


def _h(text: str) -> str:
    return html.escape(text, quote=True)
