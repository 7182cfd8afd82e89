"""What of a file is well formed when part of it is not: so that every later check still runs.

The schema's errors are reported as they are; then the values they point at are taken out of a
copy of the data (an unknown key, a bad value; a mapping left without a key it needs goes too) and
the rest is validated again, until it passes. The checks then run on what is left, and what was
taken out is remembered, so that a target naming a state taken out is not reported as unknown.
"""

from __future__ import annotations

import copy
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from hfsm import located
from hfsm.errors import Finding
from hfsm.yamlio import Document, Path_

M = TypeVar("M", bound=BaseModel)
MAX_ROUNDS = 50


def validate(model: type[M], doc: Document) -> tuple[M | None, list[Finding], set[Path_]]:
    """The model of the well-formed part of `doc`, the schema's findings, the states taken out."""
    try:
        return model.model_validate(doc.data), [], set()
    except ValidationError as exc:
        findings = located.findings(model, doc, exc.errors())
        errors = exc.errors()
    data = copy.deepcopy(doc.data)
    removed: set[Path_] = set()
    for _ in range(MAX_ROUNDS):
        paths = {located.data_path(data, err["loc"])[0] for err in errors}
        if () in paths:
            return None, findings, removed  # the file itself lacks a key it needs: nothing to check
        for path in sorted(paths, key=_order, reverse=True):
            _remove(data, path, removed)
        try:
            return model.model_validate(data), findings, removed
        except ValidationError as exc:
            errors = exc.errors()
    return None, findings, removed


def _remove(data: Any, path: Path_, removed: set[Path_]) -> None:
    """Take the value at `path` out of `data` (already gone with its parent: nothing to do)."""
    parent = data
    for part in path[:-1]:
        if not _holds(parent, part):
            return
        parent = parent[part]
    last = path[-1]
    removed.add(path)
    if _holds(parent, last):
        del parent[last]


def _holds(parent: Any, part: str | int) -> bool:
    if isinstance(parent, dict):
        return part in parent
    return isinstance(parent, list) and isinstance(part, int) and 0 <= part < len(parent)


def _order(path: Path_) -> tuple[int, list[str]]:
    """Deepest first, and the later items of a list before the earlier ones (indices stay right)."""
    return len(path), [f"{p:012d}" if isinstance(p, int) else p for p in path]


GRAPH_WARNINGS = frozenset({"W400", "W401", "W402", "W403", "W404"})


def consequences(
    findings: list[Finding], docs: dict[str, Document], removed: dict[str, set[Path_]]
) -> list[Finding]:
    """The findings less those that only follow from what was taken out of a file (`removed` and
    `docs`, by file): a target naming a state taken out, a choice whose `else` was, a mapped
    `timeout` whose timer was, and the warnings about the graph of states, which is not whole."""
    return [f for f in findings if not _follows(f, docs.get(f.file), removed.get(f.file, set()))]


def _follows(f: Finding, doc: Document | None, removed: set[Path_]) -> bool:
    if not removed or doc is None:
        return False
    if f.code in GRAPH_WARNINGS:
        return True
    if f.code in ("E301", "E316"):
        return any(f"'{p[1]}'" in f.message for p in removed if len(p) == 2 and p[0] == "states")
    if f.code == "E311":
        return any(f"choice '{p[1]}'" in f.message for p in removed if len(p) == 4 and p[2] == "choose")
    if f.code == "E309":
        return any(_inside(doc, str(p[1]), f.line) for p in removed if len(p) == 3 and p[2] == "timer")
    return False


def _inside(doc: Document, state: str, line: int) -> bool:
    """Whether `line` is in the lines of the state (from its key to the next state's)."""
    starts = sorted(pos[0] for path, pos in doc.keys.items() if len(path) == 2 and path[0] == "states")
    first = doc.keys.get(("states", state))
    if first is None:
        return False
    after = [n for n in starts if n > first[0]]
    return first[0] <= line < (after[0] if after else line + 1)
