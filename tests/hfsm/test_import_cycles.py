"""No import circles inside hfsm/: every import counts, those under TYPE_CHECKING and inside functions too."""

from __future__ import annotations

import ast
from pathlib import Path

import networkx as nx

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "hfsm"


def module_name(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def imported(tree: ast.AST, here: str, is_package: bool, known: set[str]) -> set[str]:
    """The modules of hfsm that `tree` imports (a name imported from a package counts when it is a module)."""
    found: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = here.split(".") if is_package else here.split(".")[:-1]
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join([*anchor, base] if base else anchor)
            found.add(base)
            found.update(f"{base}.{alias.name}" for alias in node.names)
    return {name for name in found if name in known}


def import_graph() -> nx.DiGraph:
    files = [p for p in PACKAGE.rglob("*.py") if "plugin_template" not in p.parts]
    known = {module_name(p) for p in files}
    graph = nx.DiGraph()
    for path in files:
        here = module_name(path)
        graph.add_node(here)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for other in imported(tree, here, path.name == "__init__.py", known):
            if other != here and not here.startswith(other + "."):  # a module's own package
                graph.add_edge(here, other)
    return graph


def test_the_graph_sees_the_engine() -> None:
    graph = import_graph()
    assert graph.has_edge("hfsm.runtime.engine", "hfsm.runtime.agent")
    assert graph.has_edge("hfsm.diagram.extract", "hfsm.diagram.regions")


def test_a_circle_is_found() -> None:
    tree = ast.parse("from hfsm.b import x\nif TYPE_CHECKING:\n    from . import c\n")
    assert imported(tree, "hfsm.a", False, {"hfsm.b", "hfsm.c"}) == {"hfsm.b", "hfsm.c"}
    graph = nx.DiGraph([("hfsm.a", "hfsm.b"), ("hfsm.b", "hfsm.a")])
    assert list(nx.simple_cycles(graph))


def test_no_import_circles_in_hfsm() -> None:
    cycles = sorted(sorted(c) for c in nx.simple_cycles(import_graph()))
    assert cycles == [], "import circles: " + "; ".join(" -> ".join(c) for c in cycles[:10])
