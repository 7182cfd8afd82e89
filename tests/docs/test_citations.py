"""Docs that stand alone: no page, docstring or message cites a document outside the repository, and
every section of docs/REFERENCE.md that one cites (`REFERENCE.md#anchor`, or `REFERENCE.md section N`)
is there under that anchor or number."""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
REFERENCE = ROOT / "docs" / "REFERENCE.md"
PLACES = ["docs", "README.md", "hfsm", "hfsm_behaviours", "hfsm_sim", "machines", "examples", "tools"]
SUFFIXES = {".md", ".py", ".yaml", ".yml", ".json", ".txt", ".js", ".html", ".dot", ".svg"}
OUTSIDE = re.compile(r"\bSPEC(?:\.md| \d| section)|\.\./shared/|/work/shared|shared/SPEC")
ANCHOR = re.compile(r"REFERENCE\.md#([A-Za-z0-9_-]+)")
NUMBERED = re.compile(r"REFERENCE(?:\.md)?,? (?:section|§) ?(\d+)")


def files() -> list[Path]:
    found: list[Path] = []
    for place in PLACES:
        path = ROOT / place
        found += [path] if path.is_file() else sorted(
            p for p in path.rglob("*") if p.is_file() and p.suffix in SUFFIXES and "__pycache__" not in p.parts)
    return found


def slug(heading: str) -> str:
    """The anchor GitHub and most Markdown renderers give a heading."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def headings() -> list[str]:
    return [line.lstrip("#").strip() for line in REFERENCE.read_text(encoding="utf-8").splitlines()
            if re.match(r"#{2,3} ", line)]


def test_the_slugs_are_those_of_the_headings() -> None:
    assert slug("`hfsm-run`") == "hfsm-run" and slug("Agents that fail") == "agents-that-fail"
    assert {"barriers", "the-trace", "hfsm-run", "expressions"} <= {slug(h) for h in headings()}


@pytest.mark.parametrize("path", files(), ids=lambda p: str(p.relative_to(ROOT)))
def test_nothing_outside_the_repository_is_cited(path: Path) -> None:
    text = path.read_text(encoding="utf-8", errors="replace")
    found = [f"{text.count(chr(10), 0, m.start()) + 1}: {m.group()}" for m in OUTSIDE.finditer(text)]
    assert not found, found


@pytest.mark.parametrize("path", [f for f in files() if f.suffix not in (".svg", ".dot")],
                         ids=lambda p: str(p.relative_to(ROOT)))  # drawings wrap a machine's doc anywhere
def test_every_cited_reference_section_exists(path: Path) -> None:
    text = path.read_text(encoding="utf-8", errors="replace")
    if path.suffix == ".svg":
        text = html.unescape(text)  # graphviz writes '-' as '&#45;'
    anchors = {slug(h) for h in headings()}
    numbered = [h for h in headings() if re.match(r"\d+\. ", h)]
    missing = [m.group(1) for m in ANCHOR.finditer(text) if m.group(1) not in anchors]
    missing += [f"section {m.group(1)}" for m in NUMBERED.finditer(text)
                if not any(h.startswith(f"{m.group(1)}. ") for h in numbered)]
    assert not missing, missing
