"""Hover, completion and definition in behaviour-test files (`*.test.yaml`).

Completion: the machines in reach after `machine:`; its params as keys of `params:` (and of each
agent's `agent_params:`); its outcomes after `outcome:` in `expect:`; the agents of the case after
`agent:`, `to:` and as keys of `agent_params:`, `by_agent:` and `expect: agents:`; the behaviours it
calls as keys of `stand_ins:`, `calls:` and `called_with:`, and a stand-in's outcomes after its
`outcome:`; outputs as keys of `outputs:` (a stand-in's, or the machine's in `expect:`). Hover: the
machine under test, a stand-in's behaviour, an outcome, a param. What the cursor is in is read from
the text before it, as in machine files (`hfsm.lsp.completion`).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from lsprotocol import types as lsp

from hfsm.builtins import BUILTINS
from hfsm.lsp.analysis import Analysis
from hfsm.lsp.hover import describe
from hfsm.lsp.locate import node_at
from hfsm.model import CallState, ParallelState
from hfsm.spec import BehaviourSpec
from hfsm.yamlio import Document

_KEY = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*:")
_FLOW_KEY = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*:\s*$")
_BLOCK = re.compile(r"^(\s*(?:-\s+)*)([A-Za-z_][A-Za-z0-9_]*)\s*:\s*(.*)$")
Kind = lsp.CompletionItemKind


@dataclass(frozen=True)
class Place:
    """Where the cursor is: the keys around it (outermost first), whether a key goes there, and the
    key whose value it is in (when not)."""

    keys: list[str]
    at_key: bool
    key: str | None


def place(lines: Sequence[str], pos: lsp.Position) -> Place:
    line = lines[pos.line] if pos.line < len(lines) else ""
    before = line[: pos.character]
    flow, segment = _flow(before)
    if not flow:  # not inside brackets: the line's own key, if any
        block = _BLOCK.match(before)
        indent = len(block.group(1)) if block else len(before) - len(before.lstrip(" -"))
        key = block.group(2) if block else None
        return Place(_parents(lines, pos.line, indent), block is None, key)
    indent = len(line) - len(line.lstrip(" -"))
    keys = [key for key, _ in flow if key]
    at_key = flow[-1][1] == "{" and ":" not in segment
    key = segment.split(":", 1)[0].strip() if ":" in segment else None
    return Place([*_parents(lines, pos.line, indent), *keys], at_key, key)


def _flow(before: str) -> tuple[list[tuple[str | None, str]], str]:
    """The brackets open at the cursor, each with the key it is the value of (None: a list's
    item); and the text since the last bracket or comma."""
    stack: list[tuple[str | None, str]] = []
    segment, quote = "", ""
    for char in before:
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char in "{[":
            found = _FLOW_KEY.search(segment)
            stack.append((found.group(1) if found else None, char))
            segment = ""
            continue
        elif char in "}]":
            if stack:
                stack.pop()
            segment = ""
            continue
        elif char == ",":
            segment = ""
            continue
        segment += char
    return stack, segment


def _parents(lines: Sequence[str], line: int, indent: int) -> list[str]:
    """The block keys above `line` that hold what is indented by `indent`, outermost first."""
    found: list[str] = []
    for n in range(line - 1, -1, -1):
        block = _BLOCK.match(lines[n])
        if block is None or lines[n].lstrip().startswith("#"):
            continue
        column = len(block.group(1))
        if column < indent:
            if not block.group(3).strip() or block.group(3).lstrip()[:1] in "#":
                found.append(block.group(2))
            indent = column
            if column == 0:
                break
    return found[::-1]


def _case(keys: list[str]) -> tuple[str | None, list[str]]:
    """The case the keys are in (None: the file's own settings), and the keys inside it."""
    if len(keys) >= 2 and keys[0] == "tests":
        return keys[1], keys[2:]
    return None, keys


def _setting(doc: Document | None, case: str | None, name: str) -> Any:
    data = doc.data if doc is not None and isinstance(doc.data, dict) else {}
    tests = data.get("tests")
    own = tests.get(case) if case and isinstance(tests, dict) else None
    if isinstance(own, dict) and own.get(name) is not None:
        return own[name]
    return data.get(name)


def subject(analysis: Analysis, doc: Document | None, case: str | None) -> BehaviourSpec | None:
    """The spec of the machine under test in `case`."""
    name = _setting(doc, case, "machine")
    if not isinstance(name, str):
        return None
    stem = name.rsplit("/", 1)[-1].removesuffix(".yaml").removesuffix(".yml")
    return analysis.specs.get(stem)


def _agents(doc: Document | None, case: str | None) -> list[str]:
    agents = _setting(doc, case, "agents")
    return [a for a in agents if isinstance(a, str)] if isinstance(agents, list) else ["robot"]


def _called(analysis: Analysis, top: BehaviourSpec | None) -> list[str]:
    """The behaviours a run of the machine may call, at any depth: what stand-ins may replace."""
    if top is None or analysis.library is None:
        return []
    machines = analysis.library.machines
    seen, pending, found = {top.name}, [top.name], []
    while pending:
        machine = machines.get(pending.pop())
        if machine is None:
            continue
        for state in machine.model.states.values():
            calls = [state.do] if isinstance(state, CallState) else []
            if isinstance(state, ParallelState):
                calls = [r.do for r in state.parallel.values()]
            for name in calls:
                if name not in seen:
                    seen.add(name)
                    found.append(name)
                    pending.append(name)
    return [n for n in found if n not in BUILTINS]


def _item(
    label: str, kind: lsp.CompletionItemKind, detail: str, spec: BehaviourSpec | None = None
) -> lsp.CompletionItem:
    doc = lsp.MarkupContent(kind=lsp.MarkupKind.Markdown, value=describe(spec)) if spec else None
    return lsp.CompletionItem(label=label, kind=kind, detail=detail, documentation=doc)


def complete(
    analysis: Analysis, doc: Document | None, lines: Sequence[str], pos: lsp.Position
) -> list[lsp.CompletionItem]:
    where = place(lines, pos)
    case, keys = _case(where.keys)
    top = subject(analysis, doc, case)
    last = keys[-1] if keys else None
    if not where.at_key:
        return _values(analysis, doc, case, keys, where.key, top)
    if last in ("params",) or (len(keys) >= 2 and keys[-2] == "agent_params"):
        params = top.params.values() if top else []
        return [_item(p.name, Kind.Property, p.type + ("" if p.required else " (optional)")) for p in params]
    if last in ("agent_params", "by_agent") or (last == "agents" and "expect" in keys):
        return [_item(a, Kind.Variable, "agent") for a in _agents(doc, case)]
    if last in ("stand_ins", "calls", "called_with"):
        return [_item(n, Kind.Function, "called", analysis.specs.get(n)) for n in _called(analysis, top)]
    if last == "outputs":
        spec = _stand_in(analysis, keys) if "stand_ins" in keys else top
        outputs = sorted(spec.outputs or ()) if spec is not None else []
        return [_item(o, Kind.Field, f"output of {spec.name}" if spec else "output") for o in outputs]
    if len(keys) >= 2 and keys[-2] == "called_with":
        spec = analysis.specs.get(keys[-1])
        return [_item(p.name, Kind.Property, p.type) for p in (spec.params.values() if spec else [])]
    return []


def _values(
    analysis: Analysis,
    doc: Document | None,
    case: str | None,
    keys: list[str],
    key: str | None,
    top: BehaviourSpec | None,
) -> list[lsp.CompletionItem]:
    if key == "machine":
        return [_item(n, Kind.Module, "machine", analysis.specs.get(n)) for n in machines_in_reach(analysis)]
    if key in ("agent", "to"):
        return [_item(a, Kind.Variable, "agent") for a in _agents(doc, case)]
    if key == "outcome":
        spec = _stand_in(analysis, keys) if "stand_ins" in keys else top
        outcomes = spec.outcomes if spec is not None else ()
        return [_item(o, Kind.EnumMember, f"outcome of {spec.name}" if spec else "outcome") for o in outcomes]
    return []


def _stand_in(analysis: Analysis, keys: Sequence[str | int]) -> BehaviourSpec | None:
    at = list(keys).index("stand_ins")
    return analysis.specs.get(str(keys[at + 1])) if at + 1 < len(keys) else None


def machines_in_reach(analysis: Analysis) -> list[str]:
    if analysis.library is None:
        return []
    others = set(BUILTINS) | set(analysis.registry.names())
    return sorted(n for n in analysis.library.known_names() if n not in others)


def hover(analysis: Analysis, doc: Document, lines: Sequence[str], pos: lsp.Position) -> lsp.Hover | None:
    text = _hover_text(analysis, doc, lines, pos)
    if text is None:
        return None
    return lsp.Hover(contents=lsp.MarkupContent(kind=lsp.MarkupKind.Markdown, value=text))


def _hover_text(analysis: Analysis, doc: Document, lines: Sequence[str], pos: lsp.Position) -> str | None:
    node = node_at(doc, lines, pos)
    if node is None:
        return None
    path = node.path
    case = str(path[1]) if len(path) >= 2 and path[0] == "tests" else None
    if path[-1] == "machine" and not node.is_key:
        spec = subject(analysis, doc, case)
        return describe(spec) if spec else None
    if len(path) >= 2 and path[-2] in ("stand_ins", "calls", "called_with") and node.is_key:
        spec = analysis.specs.get(node.text)
        return describe(spec) if spec else None
    if path[-1] == "outcome" and not node.is_key:
        spec = _stand_in(analysis, path) if "stand_ins" in path else subject(analysis, doc, case)
        if spec is None or node.text not in spec.outcomes:
            return None
        failure = " (a failure)" if node.text in spec.failures else ""
        return f"outcome **{node.text}** of `{spec.name}`{failure}\n\noutcomes: " + ", ".join(
            f"`{o}`" for o in spec.outcomes
        )
    if len(path) >= 2 and path[-2] == "params" and node.is_key:
        spec = subject(analysis, doc, case)
        param = spec.params.get(node.text) if spec else None
        if param is not None:
            return f"param **{param.name}** of `{spec.name if spec else ''}`: {param.type}" + (
                f"\n\n{param.doc}" if param.doc else ""
            )
    return None


def definition_name(doc: Document, lines: Sequence[str], pos: lsp.Position) -> str | None:
    """The behaviour whose definition the cursor asks for: the machine under test, a stand-in's."""
    node = node_at(doc, lines, pos)
    if node is None:
        return None
    if node.path[-1] == "machine" and not node.is_key:
        return node.text.rsplit("/", 1)[-1].removesuffix(".yaml").removesuffix(".yml")
    if len(node.path) >= 2 and node.path[-2] in ("stand_ins", "calls", "called_with") and node.is_key:
        return node.text
    return None
