from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
from docsection import write_section


def test_appends_then_replaces_only_its_own_section(tmp_path: Path) -> None:
    doc = tmp_path / "PERFORMANCE.md"
    write_section(doc, "a", ["first"])
    assert doc.read_text() == "<!-- a:start -->\nfirst\n<!-- a:end -->\n"
    doc.write_text("# Title\n\n" + doc.read_text() + "\nbetween\n")
    write_section(doc, "b", ["bee"])
    write_section(doc, "a", ["new", "lines"])
    assert doc.read_text() == (
        "# Title\n\n<!-- a:start -->\nnew\nlines\n<!-- a:end -->\n\nbetween\n\n<!-- b:start -->\nbee\n<!-- b:end -->\n"
    )
