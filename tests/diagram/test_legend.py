from __future__ import annotations

from hfsm.diagram.dot import ROLE, STYLE, to_dot
from hfsm.diagram.legend import legend
from hfsm.diagram.model import nodes
from hfsm.diagram.render import render


def test_the_legend_shows_every_role_and_every_arc_style() -> None:
    fig = legend()
    roles = {n.role for n in nodes(fig)}
    assert set(ROLE) <= roles
    styles = {e.style for e in fig.edges}
    assert {"success", "failure", "message"} <= styles <= set(STYLE)
    assert any(e.count for e in fig.edges)


def test_the_legend_renders() -> None:
    svg = render(to_dot(legend()), "svg")
    assert b"<svg" in svg and b"any state" in svg
