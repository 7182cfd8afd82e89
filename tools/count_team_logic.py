"""Lines of the team's logic, in Python and in machine files (issue 21, item 3).

    .venv/bin/python tools/count_team_logic.py [--json]

What counts as a line: a line of code, neither blank, nor a comment, nor inside a docstring
(Python: by its tokens); in a machine file, neither blank, nor a comment, nor the text of a `doc:`
(its first line and the lines folded under it). Counted:

- Python, the team's code: every module of `hfsm_behaviours/teamwork/`, `hfsm_behaviours/tararc/`
  and `hfsm_behaviours/room/`; among them, the protocols: the modules of primitives that hear, say
  and decide for the team (`teamwork/` but `walk.py`, the room's walks), the room's plan and
  recovery decisions (`room/plan.py`, `room/recovery.py`) and the pure data of the exchange and the
  news (`tararc/holdings.py`, `room/news.py`); and the functions and classes issue 21 names
  (`NAMED`, wherever they stand in those folders, their docstrings left out).
- YAML, the team's machines: `machines/tararc*.yaml`, `machines/room_*.yaml`,
  `machines/clear_room.yaml`.
"""

from __future__ import annotations

import argparse
import ast
import io
import json
import re
import sys
import textwrap
import tokenize
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PYTHON_FOLDERS = ("hfsm_behaviours/teamwork", "hfsm_behaviours/tararc", "hfsm_behaviours/room")
PROTOCOLS = ("hfsm_behaviours/teamwork/[!_w]*.py", "hfsm_behaviours/room/plan.py",
             "hfsm_behaviours/room/recovery.py", "hfsm_behaviours/room/news.py",
             "hfsm_behaviours/tararc/holdings.py")
NAMED = ("Holdings", "tararc_exchange", "job_of", "_job_in", "groups_after", "sliding_partners", "channel_of",
         "room_watch")
MACHINES = ("machines/tararc*.yaml", "machines/room_*.yaml", "machines/clear_room.yaml")
_DOC = re.compile(r"^(\s*)(- )?doc:")


def python_lines(text: str) -> int:
    """Lines holding a token that is code (not a comment, not a docstring, not a line break)."""
    lines: set[int] = set()
    previous = tokenize.NEWLINE
    for tok in tokenize.generate_tokens(io.StringIO(text).readline):
        kind = tok.type
        if kind == tokenize.STRING and previous in (tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT):
            previous = kind  # a docstring, or a bare string standing as a statement
            continue
        if kind not in (tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT,
                        tokenize.ENDMARKER):
            lines.update(range(tok.start[0], tok.end[0] + 1))
        if kind not in (tokenize.COMMENT, tokenize.NL):
            previous = kind
    return len(lines)


def yaml_lines(text: str) -> int:
    """Lines that are neither blank, a comment, nor a `doc:` and the lines folded under it."""
    count, doc_indent = 0, -1
    for line in text.splitlines():
        stripped = line.strip()
        indent = len(line) - len(line.lstrip())
        if doc_indent >= 0:
            if not stripped or indent > doc_indent:
                continue
            doc_indent = -1
        if not stripped or stripped.startswith("#"):
            continue
        match = _DOC.match(line)
        if match:
            doc_indent = indent + (2 if match.group(2) else 0)
            continue
        count += 1
    return count


def named_lines(path: Path) -> dict[str, int]:
    """The code lines of each top-level function or class of `NAMED` in one module."""
    text = path.read_text(encoding="utf-8")
    lines = text.splitlines(keepends=True)
    out = {}
    for node in ast.parse(text).body:
        if isinstance(node, ast.FunctionDef | ast.ClassDef) and node.name in NAMED:
            start = min([node.lineno, *(d.lineno for d in node.decorator_list)])
            out[node.name] = python_lines(textwrap.dedent("".join(lines[start - 1:node.end_lineno])))
    return out


def files(root: Path, patterns: tuple[str, ...]) -> list[Path]:
    return sorted({p for pattern in patterns for p in root.glob(pattern)})


def count(root: Path = ROOT) -> dict[str, object]:
    python = {str(p.relative_to(root)): python_lines(p.read_text(encoding="utf-8"))
              for folder in PYTHON_FOLDERS for p in sorted((root / folder).glob("*.py"))}
    protocols = {str(p.relative_to(root)): python[str(p.relative_to(root))] for p in files(root, PROTOCOLS)}
    named = {f"{p.relative_to(root)}:{name}": n for folder in PYTHON_FOLDERS
             for p in sorted((root / folder).glob("*.py")) for name, n in named_lines(p).items()}
    machines = {str(p.relative_to(root)): yaml_lines(p.read_text(encoding="utf-8"))
                for p in files(root, MACHINES)}
    return {"python": sum(python.values()), "python_protocols": sum(protocols.values()),
            "python_named": sum(named.values()),
            "yaml": sum(machines.values()), "python_files": python, "protocol_files": protocols,
            "named": named, "machine_files": machines}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--json", action="store_true", help="one JSON object on stdout")
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout to count (default: this one)")
    args = parser.parse_args(argv)
    counts = count(args.root.resolve())
    if args.json:
        print(json.dumps(counts, indent=1))
        return 0
    for title, key in (("Python protocols", "protocol_files"), ("named in issue 21", "named"),
                       ("machines", "machine_files")):
        print(f"{title}:")
        for name, n in dict(counts[key]).items():  # type: ignore[call-overload]
            print(f"  {n:5d}  {name}")
    print(f"Python, teamwork/ tararc/ room/: {counts['python']} lines of code")
    print("  of which protocols (teamwork/ but walk.py; room/plan, recovery, news; tararc/holdings):",
          counts["python_protocols"])
    print(f"  of which the functions issue 21 names: {counts['python_named']}")
    print(f"YAML, the team's machines: {counts['yaml']} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
