"""Golden DOT files: the same machine files give the same bytes. HFSM_UPDATE_GOLDEN=1 rewrites them."""

from __future__ import annotations

import os

import pytest

from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import machine_figure, overview
from hfsm.diagram.legend import legend
from hfsm.diagram.model import Edge, Figure, Node

from .helpers_diagram import GOLDEN, data_sources

CASES = [
    ("lift", 0),
    ("move_table", 0),
    ("move_table", 1),
    ("relay", 0),
    ("relay", 2),
    ("search", 0),
    ("search", 2),
]


def _golden(name: str, dot: str) -> None:
    path = GOLDEN / f"{name}.dot"
    if os.environ.get("HFSM_UPDATE_GOLDEN"):
        path.write_text(dot, encoding="utf-8")
    assert path.is_file(), f"no golden file {path}: run with HFSM_UPDATE_GOLDEN=1"
    assert dot == path.read_text(encoding="utf-8"), (
        f"{path} differs: run with HFSM_UPDATE_GOLDEN=1 if intended"
    )


@pytest.mark.parametrize(("machine", "depth"), CASES)
def test_machine_figures_match_their_golden_dot(machine: str, depth: int) -> None:
    src = data_sources()
    dot = to_dot(machine_figure(machine, src, depth, links=set(src.machines)))
    _golden(f"{machine}.depth{depth}", dot)


def test_overview_and_legend_match_their_golden_dot() -> None:
    _golden("call-graph", to_dot(overview(data_sources(), ["relay"], links={"relay"})))
    _golden("legend", to_dot(legend()))


def test_the_same_figure_gives_the_same_bytes() -> None:
    first = to_dot(machine_figure("relay", data_sources(), 2))
    again = to_dot(machine_figure("relay", data_sources(), 2))
    assert first == again


def test_attributes_are_sorted_and_text_is_escaped() -> None:
    fig = Figure(
        name='a "b"',
        title="t<1>",
        items=(Node("x", "primitive", "x", ('say(text="a & b")',), tooltip='q"\\'),),
        edges=(Edge("x", "x", ("1: a < b",), "failure"),),
    )
    dot = to_dot(fig)
    assert dot.startswith('digraph "a \\"b\\"" {')
    assert "<b>t&lt;1&gt;</b>" in dot
    assert "say(text=&quot;a &amp; b&quot;)" in dot
    assert 'tooltip="q\\"\\\\"' in dot
    assert '"x" -> "x" [label="1: a < b", style="dashed"];' in dot
    node_line = next(line for line in dot.splitlines() if line.startswith('  "x" ['))
    keys = [part.split("=")[0] for part in node_line[node_line.index("[") + 1 :].split(", ") if "=" in part]
    assert keys == sorted(keys)


def test_links_point_to_figures_of_the_chosen_format() -> None:
    src = data_sources()
    fig = machine_figure("relay", src, links={"move_table"})
    assert 'href="move_table.svg"' in to_dot(fig)
    assert 'href="move_table.pdf"' in to_dot(fig, link_ext="pdf")


def test_a_linked_state_without_a_doc_shows_its_machine_as_tooltip_not_html() -> None:
    src = data_sources()
    dot = to_dot(machine_figure("relay", src, links={"move_table"}))
    line = next(line for line in dot.splitlines() if 'href="move_table.svg"' in line)
    assert 'tooltip="move_table"' in line
