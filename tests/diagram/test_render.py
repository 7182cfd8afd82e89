"""Rendering through pygraphviz: every machine of the repository draws, as SVG and PNG."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

import pytest

from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import Sources, machine_figure
from hfsm.diagram.render import RenderError, render
from hfsm.errors import UserError
from hfsm.load import load
from hfsm.registry import Registry

from .helpers_diagram import DATA, repository_machines

SVG = "{http://www.w3.org/2000/svg}"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
FILES = sorted(DATA.glob("*.yaml")) + repository_machines()


def _svg_nodes(svg: bytes) -> Counter[str]:
    """The title of each node group in Graphviz's SVG: the node's id."""
    root = ET.fromstring(svg)
    return Counter(g.findtext(f"{SVG}title") or "" for g in root.iter(f"{SVG}g") if g.get("class") == "node")


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_machine_draws_one_svg_node_per_state_and_outcome(path: Path) -> None:
    registry = Registry.discover()
    try:
        loaded = load([path], registry=registry)
    except UserError as err:
        pytest.fail(f"every machine must load and draw; this one does not: {err.findings[0].format()}")
    src = Sources.from_loaded(loaded, registry)
    name = loaded.roots[0].name
    dot = to_dot(machine_figure(name, src))
    found = _svg_nodes(render(dot, "svg"))
    m = src.machines[name]
    for node in [*m.states, *m.all_outcomes]:
        assert found[node] == 1, node
    png = render(dot, "png")
    assert png.startswith(PNG_MAGIC) and len(png) > 1000


def test_pdf_and_dot() -> None:
    dot = 'digraph "g" { "a" -> "b"; }\n'
    assert render(dot, "pdf").startswith(b"%PDF")
    assert render(dot, "dot") == dot.encode()


def test_graphviz_failures_are_render_errors() -> None:
    with pytest.raises(RenderError):
        render("digraph {", "svg")
