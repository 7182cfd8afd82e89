"""Shared by the diagram tests: the test machines, loaded; node ids declared in DOT text."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

from hfsm.diagram.extract import Sources
from hfsm.load import load
from hfsm.registry import Registry

DATA = Path(__file__).resolve().parent / "data"
GOLDEN = Path(__file__).resolve().parent / "golden"
ROOT = Path(__file__).resolve().parents[2]
_DECLARED = re.compile(r'^\s*"((?:[^"\\]|\\.)*)" \[', re.MULTILINE)


def data_sources() -> Sources:
    registry = Registry.discover()
    loaded = load(sorted(DATA.glob("*.yaml")), registry=registry)
    return Sources.from_loaded(loaded, registry)


def declared(dot: str) -> Counter[str]:
    """How often each node id is declared (`"id" [` at the start of a line) in DOT text."""
    return Counter(_DECLARED.findall(dot))


def repository_machines() -> list[Path]:
    """Every machine file of the repository's machines/ and examples/, whatever exists now."""
    return sorted(p for folder in ("machines", "examples") for p in (ROOT / folder).glob("*.y*ml"))
