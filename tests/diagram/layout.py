"""Where Graphviz put every node and every label of a figure, as boxes in points (its JSON output)."""

from __future__ import annotations

import json
from collections.abc import Iterator, Mapping, Sequence
from typing import Any

from hfsm.diagram.render import render

Box = tuple[float, float, float, float]  # x0, y0, x1, y1
_ALIGN = {"l": 0.0, "c": 0.5, "r": 1.0}


def _texts(ops: Sequence[Mapping[str, Any]] | None) -> Iterator[Box]:
    """The box of each text drawn: from its baseline point, width and the font size before it."""
    size = 14.0
    for op in ops or ():
        if op["op"] == "F":
            size = float(op["size"])
        elif op["op"] == "T":
            x, y = op["pt"]
            x0 = x - _ALIGN[op["align"]] * op["width"]
            yield (x0, y - 0.25 * size, x0 + op["width"], y + 0.75 * size)


def _union(boxes: list[Box]) -> Box | None:
    if not boxes:
        return None
    return (
        min(b[0] for b in boxes),
        min(b[1] for b in boxes),
        max(b[2] for b in boxes),
        max(b[3] for b in boxes),
    )


def boxes(dot: str) -> tuple[dict[str, Box], dict[str, Box]]:
    """(visible nodes, labels) of a figure laid out by Graphviz; labels are arcs', clusters', the caption."""
    layout = json.loads(render(dot, "json"))
    objects = layout.get("objects", [])
    nodes: dict[str, Box] = {}
    labels: dict[str, Box] = {}
    caption = _union(list(_texts(layout.get("_ldraw_"))))
    if caption:
        labels["caption"] = caption
    for o in objects:
        if "pos" not in o:  # a subgraph: a cluster's label
            label = _union(list(_texts(o.get("_ldraw_"))))
            if label and str(o["name"]).startswith("cluster"):
                labels[f"cluster {o['name']}"] = label
            continue
        x, y = map(float, o["pos"].split(","))
        w, h = float(o["width"]) * 36, float(o["height"]) * 36
        if "invis" not in o.get("style", ""):
            nodes[o["name"]] = (x - w, y - h, x + w, y + h)
        if o.get("xlabel"):
            xl = [b for b in _texts(o.get("_ldraw_")) if not _inside(b, nodes.get(o["name"]))]
            if box := _union(xl):
                labels[f"xlabel of {o['name']}"] = box
    for e in layout.get("edges", []):
        arc = f"{objects[e['tail']]['name']} -> {objects[e['head']]['name']}"
        for key in ("_ldraw_", "_tldraw_", "_hldraw_"):
            if box := _union(list(_texts(e.get(key)))):
                labels[f"label {e.get('label', '')!r} of {arc}"] = box
    return nodes, labels


def _inside(b: Box, outer: Box | None) -> bool:
    return (
        outer is not None and outer[0] <= b[0] and outer[1] <= b[1] and b[2] <= outer[2] and b[3] <= outer[3]
    )


def _meet(a: Box, b: Box, tolerance: float = 0.5) -> bool:
    return (
        a[0] < b[2] - tolerance
        and b[0] < a[2] - tolerance
        and a[1] < b[3] - tolerance
        and b[1] < a[3] - tolerance
    )


def overlaps(dot: str) -> list[str]:
    """Every pair of labels that overlap, and every label that overlaps a node."""
    nodes, labels = boxes(dot)
    found = []
    names = sorted(labels)
    for i, a in enumerate(names):
        found += [f"{a} overlaps {b}" for b in names[i + 1 :] if _meet(labels[a], labels[b])]
        found += [f"{a} overlaps node {n}" for n, box in nodes.items() if _meet(labels[a], box)]
    return found
