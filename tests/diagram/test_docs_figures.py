"""The committed figures (docs/figures) are those of today's machines: regenerate with `make figures`."""

from __future__ import annotations

from pathlib import Path

import pytest

from hfsm.cli.graph import build_parser, draw
from hfsm.errors import UserError

from .helpers_diagram import ROOT

FIGURES = ROOT / "docs" / "figures"
# (folder of machine files, folder of their committed figures, extra hfsm-graph arguments): as in the Makefile
SETS = [
    ("machines", FIGURES, []),
    ("examples", FIGURES / "examples", ["--no-legend"]),
    ("tests/diagram/data/search.yaml", FIGURES / "depth", ["--depth", "2", "--no-legend", "--no-overview"]),
]


@pytest.mark.parametrize(("machines", "figures", "extra"), SETS, ids=[s[0] for s in SETS])
def test_committed_figures_are_up_to_date(machines: str, figures: Path, extra: list[str]) -> None:
    args = build_parser().parse_args([str(ROOT / machines), "--format", "dot", *extra])
    try:
        drawn = draw(args)
    except UserError as err:
        pytest.fail(f"{machines}/ does not load: {err.findings[0].format()}")
    fresh = {name: data.decode("utf-8") for name, data in drawn.items()}
    committed = {p.name: p.read_text(encoding="utf-8") for p in sorted(figures.glob("*.dot"))}
    hint = "docs/figures is stale: run `make figures` and commit docs/figures"
    assert sorted(committed) == sorted(fresh), hint
    for name, dot in fresh.items():
        assert committed[name] == dot, f"{name}: {hint}"
        assert (figures / name).with_suffix(".svg").is_file(), f"{name}: no SVG beside it; {hint}"
