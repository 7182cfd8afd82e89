"""Figures that read whole: no label overlaps another label or a node, in every committed figure and
in the v2 test machine at every depth (checked on Graphviz's own layout, not on our DOT)."""

from __future__ import annotations

from pathlib import Path

import pytest

from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import machine_figure

from .helpers_diagram import DATA, ROOT, data_sources
from .layout import boxes, overlaps

FIGURES = sorted((ROOT / "docs" / "figures").rglob("*.dot"))


@pytest.mark.parametrize(
    "path", FIGURES, ids=[str(p.relative_to(ROOT / "docs" / "figures")) for p in FIGURES]
)
def test_no_label_overlaps_in_committed_figures(path: Path) -> None:
    assert overlaps(path.read_text(encoding="utf-8")) == []


@pytest.mark.parametrize("depth", [0, 1, 2])
def test_no_label_overlaps_in_v2_figures_at_any_depth(depth: int) -> None:
    src = data_sources()
    for name in ("search", "move_table", "relay"):
        assert overlaps(to_dot(machine_figure(name, src, depth))) == [], name


def test_the_check_sees_an_xlabel_forced_onto_a_node() -> None:
    # machines/move_table --depth 2 as drawn before a timer's duration became a node beside it
    dot = (DATA / "overlapping.dot").read_text(encoding="utf-8")
    nodes, labels = boxes(dot)
    assert {"@timer", "@any", "align/look"} <= set(nodes) and "xlabel of @timer" in labels
    assert overlaps(dot) == ["xlabel of @timer overlaps node @any"]
