"""Go to definition, references, rename and document symbols.

A name is a state, an outcome, a var, a param or a behaviour. Its places in a file: its declaration
(a state's key, an entry of `outcomes`, a key of `vars` or `params`), the targets that name a state
or an outcome, `save` keys and `vars.x` in expressions for a var, `params.x` for a param. An
outcome is also named by its callers, as `on:` keys and `retry: on:` entries of the states that
call its machine.
"""

from __future__ import annotations

import importlib.util
import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from lsprotocol import types as lsp

from hfsm.library import MachineFile
from hfsm.lsp.locate import Node, dotted_at, name_range, node_at, value_at
from hfsm.model import CallState
from hfsm.yamlio import Path_

Lines = Callable[[Path], Sequence[str]]


@dataclass(frozen=True)
class Name:
    kind: str  # state, outcome, var, param, behaviour
    text: str


def is_target(path: Path_) -> bool:
    if path == ("initial",) or (len(path) == 2 and path[0] == "any"):
        return True
    if path[-1:] in (("then",), ("else",)):
        return True
    return len(path) == 4 and path[0] == "states" and path[2] == "on"


def name_at(machine: MachineFile, lines: Sequence[str], pos: lsp.Position) -> Name | None:
    node = node_at(machine.doc, lines, pos)
    named = _named(machine, node) if node is not None else None
    if named is not None:
        return named
    dotted = dotted_at(lines, pos)
    return _dotted(dotted[0]) if dotted else None


def _dotted(text: str) -> Name | None:
    head, _, name = text.partition(".")
    kinds = {"vars": "var", "params": "param"}
    return Name(kinds[head], name.split(".")[0]) if head in kinds and name else None


def _named(machine: MachineFile, node: Node) -> Name | None:
    path, m = node.path, machine.model
    if node.is_key and len(path) == 2 and path[0] in ("states", "vars", "params"):
        return Name({"states": "state", "vars": "var", "params": "param"}[str(path[0])], node.text)
    if not node.is_key and len(path) == 2 and path[0] == "outcomes":
        return Name("outcome", node.text)
    if not node.is_key and len(path) == 2 and path[0] == "untraced":
        return Name("var", node.text)
    if node.is_key and "save" in path[-2:-1]:
        return Name("var", node.text)
    if not node.is_key and path[-1] == "do":
        return Name("behaviour", node.text)
    if not node.is_key and is_target(path):
        return Name("state" if node.text in m.states else "outcome", node.text)
    return None


def occurrences(machine: MachineFile, lines: Sequence[str], name: Name) -> list[lsp.Range]:
    """Every place the name is written in the machine's own file."""
    doc, found = machine.doc, []
    for path, (line, col) in doc.keys.items():
        if path[-1] == name.text and _declares(path, name):
            found.append(name_range(lines, line, col)[0])
    for path, (line, col) in doc.values.items():
        value = value_at(doc, path)
        if value == name.text and _names(path, name):
            found.append(name_range(lines, line, col)[0])
    if name.kind in ("var", "param"):
        found += _in_text(lines, f"{'vars' if name.kind == 'var' else 'params'}.{name.text}")
    return sorted(found, key=lambda r: (r.start.line, r.start.character))


def _declares(path: Path_, name: Name) -> bool:
    if name.kind == "state":
        return len(path) == 2 and path[0] == "states"
    if name.kind == "var":
        return (len(path) == 2 and path[0] == "vars") or (len(path) >= 2 and path[-2] == "save")
    if name.kind == "param":
        return len(path) == 2 and path[0] == "params"
    return False


def _names(path: Path_, name: Name) -> bool:
    if name.kind in ("state", "outcome") and is_target(path):
        return True
    if name.kind == "var":
        return len(path) == 2 and path[0] == "untraced"
    return name.kind == "outcome" and len(path) == 2 and path[0] in ("outcomes", "failures")


def _in_text(lines: Sequence[str], dotted: str) -> list[lsp.Range]:
    pattern = re.compile(rf"\b{re.escape(dotted)}\b")
    found = []
    for n, text in enumerate(lines):
        for match in pattern.finditer(text):
            start = match.start() + dotted.index(".") + 1
            found.append(lsp.Range(lsp.Position(n, start), lsp.Position(n, match.end())))
    return found


def caller_occurrences(
    machines: dict[str, MachineFile], callee: str, outcome: str, lines_of: Lines
) -> Iterator[tuple[Path, lsp.Range]]:
    """Where callers of `callee` name its `outcome`: their `on:` keys and `retry: on:` entries."""
    for mf in machines.values():
        if mf.name == callee:
            continue
        lines = lines_of(mf.path)
        for state_name, state in mf.model.states.items():
            if not isinstance(state, CallState) or state.do != callee:
                continue
            key = mf.doc.keys.get(("states", state_name, "on", outcome))
            if key is not None:
                yield mf.path.resolve(), name_range(lines, *key)[0]
            for i, event in enumerate(state.retry.on if state.retry else []):
                at = mf.doc.values.get(("states", state_name, "retry", "on", i))
                if event == outcome and at is not None:
                    yield mf.path.resolve(), name_range(lines, *at)[0]


def definition(machine: MachineFile, lines: Sequence[str], name: Name) -> lsp.Range | None:
    """Where a state, outcome, var or param of this file is declared."""
    table = {"state": ("states", True), "var": ("vars", True), "param": ("params", True)}
    if name.kind in table:
        at = machine.doc.keys.get((table[name.kind][0], name.text))
        return name_range(lines, *at)[0] if at else None
    if name.kind == "outcome" and name.text in machine.model.outcomes:
        at = machine.doc.values.get(("outcomes", machine.model.outcomes.index(name.text)))
        return name_range(lines, *at)[0] if at else None
    return None


def python_definition(target: str) -> tuple[Path, int] | None:
    """The file and 0-based line of a primitive's function (`module:function`), without importing it."""
    module, _, function = target.partition(":")
    try:
        spec = importlib.util.find_spec(module)
    except (ImportError, ValueError):
        return None
    if spec is None or spec.origin is None or not spec.origin.endswith(".py"):
        return None
    path = Path(spec.origin)
    pattern = re.compile(rf"^\s*(?:async\s+)?def\s+{re.escape(function)}\b|^{re.escape(function)}\s*=")
    for n, text in enumerate(path.read_text(encoding="utf-8").splitlines()):
        if pattern.match(text):
            return path, n
    return path, 0


def symbols(machine: MachineFile, lines: Sequence[str]) -> list[lsp.DocumentSymbol]:
    """The machine's states, params, vars and outcomes, in the order they are written."""
    kinds = {
        "states": lsp.SymbolKind.Class,
        "params": lsp.SymbolKind.Property,
        "vars": lsp.SymbolKind.Variable,
    }
    found = []
    for path, (line, col) in machine.doc.keys.items():
        if len(path) == 2 and path[0] in kinds:
            rng = name_range(lines, line, col)[0]
            detail = _detail(machine, str(path[0]), str(path[1]))
            found.append(lsp.DocumentSymbol(str(path[1]), kinds[str(path[0])], rng, rng, detail=detail))
    for i, outcome in enumerate(machine.model.outcomes):
        at = machine.doc.values.get(("outcomes", i))
        if at is not None:
            rng = name_range(lines, *at)[0]
            found.append(lsp.DocumentSymbol(outcome, lsp.SymbolKind.EnumMember, rng, rng, detail="outcome"))
    return sorted(found, key=lambda s: (s.range.start.line, s.range.start.character))


def _detail(machine: MachineFile, section: str, name: str) -> str:
    if section == "states":
        state = machine.model.states.get(name)
        return f"do {state.do}" if isinstance(state, CallState) else "state"
    return section[:-1]
