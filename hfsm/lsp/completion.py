"""Completion: behaviour names after `do:`, the callee's params in `with`, its outcomes as `on:`
keys, targets, messages, vars, params and inputs.

What the cursor is in is read from the text before it (the line, and the lines above for an
indented block), since the document is being typed and may not parse; the names come from the
latest well-read version of the machine.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

from lsprotocol import types as lsp

from hfsm.library import MachineFile
from hfsm.lsp.analysis import Analysis
from hfsm.lsp.hover import describe
from hfsm.model import CallState, Machine
from hfsm.spec import BehaviourSpec, ParamSpec

_EXPR = re.compile(r"\b(vars|params|in|state)\.([A-Za-z0-9_]*)$")
_DO = re.compile(r"(?:^|[\s{,])do:\s*([a-z0-9_]*)$")
_TARGET = re.compile(r"(?:^|[\s{,])(?:then|else|initial):\s*([a-z0-9_]*)$")
_UNTRACED = re.compile(r"^\s*untraced:\s*\[[^\]]*$")  # in `untraced: [..`, a var
_FLOW_KEY = re.compile(r"([a-z_]+):\s*\{([^{}]*)$")
_BLOCK_KEY = re.compile(r"^\s*(?:-\s+)?([a-z_]+):\s*(?:#.*)?$")
_VALUE = re.compile(r"(?:^|[\s{,])([a-z_][a-z0-9_]*):\s*([a-z_]*)$")
_STATE_FIELDS = ("time", "attempt")

Kind = lsp.CompletionItemKind


def complete(
    analysis: Analysis, machine: MachineFile | None, lines: Sequence[str], pos: lsp.Position
) -> list[lsp.CompletionItem]:
    line = lines[pos.line] if pos.line < len(lines) else ""
    before = line[: pos.character]
    expr = _EXPR.search(before)
    model = machine.model if machine is not None else None
    if expr is not None:
        return _expression(analysis, model, expr.group(1))
    if _DO.search(before):
        return _behaviours(analysis)
    if model is None:
        return []
    if _TARGET.search(before):
        return _targets(model)
    key, at_key = _enclosing(lines, pos.line, before)
    state = _state_at(machine, pos.line) if machine is not None else None
    callee = analysis.specs.get(state.do) if isinstance(state, CallState) else None
    if key == "with" and callee is not None:
        if not at_key:
            return _values(callee.params, before)
        params = callee.params.values()
        return [_item(p.name, Kind.Property, p.type + ("" if p.required else " (optional)")) for p in params]
    if key in ("on", "any"):
        if not at_key:
            return _targets(model)
        events = [*(callee.outcomes if callee and key == "on" else ()), "error", *model.receives]
        if key == "on" and state is not None and getattr(state, "timer", None) is not None:
            events.append("timeout")
        return [_item(e, Kind.Event, "event") for e in dict.fromkeys(events)]
    return _vars_or_outputs(model, callee, key if not _UNTRACED.search(before) else "untraced", at_key)


def _vars_or_outputs(
    model: Machine, callee: BehaviourSpec | None, key: str | None, at_key: bool
) -> list[lsp.CompletionItem]:
    """A `save`'s var (key) or callee's output (value); an `untraced` list's vars."""
    if key == "untraced" or (key == "save" and at_key):
        return [_item(v, Kind.Variable, "var") for v in model.vars]
    if key == "save":
        outputs = sorted(callee.outputs or ()) if callee else []
        return [_item(o, Kind.Field, "output") for o in outputs]
    return []


def _item(label: str, kind: lsp.CompletionItemKind, detail: str, doc: str = "") -> lsp.CompletionItem:
    documentation = lsp.MarkupContent(kind=lsp.MarkupKind.Markdown, value=doc) if doc else None
    return lsp.CompletionItem(label=label, kind=kind, detail=detail, documentation=documentation)


def _values(params: Mapping[str, ParamSpec], before: str) -> list[lsp.CompletionItem]:
    """The values of the param whose value the cursor is at, when it takes a fixed set (`keep`)."""
    at = _VALUE.search(before)
    param = params.get(at.group(1)) if at is not None else None
    if param is None:
        return []
    return [_item(c, Kind.EnumMember, param.name, param.doc) for c in param.choices]


def _behaviours(analysis: Analysis) -> list[lsp.CompletionItem]:
    items = []
    for name in analysis.known_behaviours():
        spec = analysis.specs.get(name)
        kind = spec.kind if spec is not None else "machine"
        items.append(_item(name, Kind.Function, kind, describe(spec) if spec is not None else ""))
    return items


def _targets(model: Machine) -> list[lsp.CompletionItem]:
    states = [_item(s, Kind.Class, "state") for s in model.states]
    return states + [_item(o, Kind.EnumMember, "outcome") for o in model.all_outcomes]


def _expression(analysis: Analysis, model: Machine | None, head: str) -> list[lsp.CompletionItem]:
    if head == "in":
        inputs = analysis.inputs or {}
        return [_item(n, Kind.Field, s.type, s.doc) for n, s in inputs.items()]
    if head == "state":
        return [_item(n, Kind.Field, "state") for n in _STATE_FIELDS]
    if model is None:
        return []
    if head == "vars":
        return [_item(n, Kind.Variable, "var") for n in model.vars]
    return [_item(n, Kind.Variable, p.type, p.doc or "") for n, p in model.params.items()]


def _enclosing(lines: Sequence[str], line: int, before: str) -> tuple[str | None, bool]:
    """The key whose mapping the cursor is in, and whether the cursor is where a key goes."""
    flow = _FLOW_KEY.search(before)
    if flow is not None:
        entry = re.split(r",", flow.group(2))[-1]
        return flow.group(1), ":" not in entry
    indent = len(before) - len(before.lstrip())
    at_key = ":" not in before
    for n in range(line - 1, -1, -1):
        text = lines[n]
        if not text.strip() or text.lstrip().startswith("#"):
            continue
        if len(text) - len(text.lstrip()) < indent:
            block = _BLOCK_KEY.match(text)
            return (block.group(1) if block else None), at_key
    return None, at_key


def _state_at(machine: MachineFile, line: int) -> object:
    """The state whose key is the last one at or above the 0-based `line`."""
    best, best_line = None, -1
    for path, (key_line, _) in machine.doc.keys.items():
        if len(path) == 2 and path[0] == "states" and best_line < key_line - 1 <= line:
            best, best_line = machine.model.states.get(str(path[1])), key_line - 1
    return best
