"""Hover: a callee's doc, params, outcomes, failures and outputs; a state's callee and targets; a
param of `with`; `in.x`'s type and unit; a var's or a param's declaration."""

from __future__ import annotations

import json
from collections.abc import Sequence

from lsprotocol import types as lsp

from hfsm.library import MachineFile
from hfsm.lsp.analysis import Analysis
from hfsm.lsp.locate import dotted_at, node_at
from hfsm.model import CallState, ChoiceState, ParallelState
from hfsm.spec import BehaviourSpec


def describe(spec: BehaviourSpec) -> str:
    """A behaviour as Markdown: what it is, its doc, and what a caller must know."""
    lines = [f"**{spec.name}** ({spec.kind}{f', world {spec.world}' if spec.world else ''})"]
    if spec.doc:
        lines += ["", spec.doc.strip()]
    if spec.params:
        lines += ["", "params:"]
        lines += [f"- `{p.name}`: {p.type}{_default(p.required, p.default)}" for p in spec.params.values()]
    lines += ["", "outcomes: " + ", ".join(f"`{o}`" for o in spec.outcomes)]
    if spec.failures:
        lines.append("failures: " + ", ".join(f"`{o}`" for o in sorted(spec.failures)))
    if spec.outputs is None:
        lines.append("outputs: any")
    elif spec.outputs:
        lines.append("outputs: " + ", ".join(f"`{o}`" for o in sorted(spec.outputs)))
    return "\n".join(lines)


def _default(required: bool, default: object) -> str:
    return " (required)" if required else f" = {json.dumps(default, default=str)}"


def hover(
    analysis: Analysis, machine: MachineFile, lines: Sequence[str], pos: lsp.Position
) -> lsp.Hover | None:
    text = _expression_name(analysis, machine, lines, pos)
    if text is None:
        text = _node_text(analysis, machine, lines, pos)
    if text is None:
        return None
    return lsp.Hover(contents=lsp.MarkupContent(kind=lsp.MarkupKind.Markdown, value=text))


def _expression_name(
    analysis: Analysis, machine: MachineFile, lines: Sequence[str], pos: lsp.Position
) -> str | None:
    found = dotted_at(lines, pos)
    if found is None:
        return None
    head, _, name = found[0].partition(".")
    m = machine.model
    if head == "in" and analysis.inputs is not None and name in analysis.inputs:
        spec = analysis.inputs[name]
        return f"**in.{name}**: {spec.type}\n\n{spec.doc}"
    if head == "vars" and name in m.vars:
        return f"**vars.{name}**: starts as `{json.dumps(m.vars[name], default=str)}`"
    if head == "params" and name in m.params:
        p = m.params[name]
        doc = f"\n\n{p.doc}" if p.doc else ""
        return f"**params.{name}**: {p.type}{_default(p.required, p.default)}{doc}"
    return None


def _node_text(
    analysis: Analysis, machine: MachineFile, lines: Sequence[str], pos: lsp.Position
) -> str | None:
    node = node_at(machine.doc, lines, pos)
    if node is None:
        return None
    path, m, specs = node.path, machine.model, analysis.specs
    if path[-1:] == ("do",) or (len(path) > 2 and path[-1] == "do"):
        spec = specs.get(node.text)
        return describe(spec) if spec else None
    if len(path) == 2 and path[0] == "states" and node.is_key:
        return _state(machine, str(path[1]), specs)
    if not node.is_key and node.text in m.states and path[0] in ("states", "any", "watch", "initial"):
        return f"target: state **{node.text}**\n\n" + (_state(machine, node.text, specs) or "")
    if not node.is_key and node.text in m.all_outcomes and path[0] in ("states", "any", "watch"):
        return f"target: outcome **{node.text}** of machine `{machine.name}` (the machine ends)"
    if len(path) == 4 and path[0] == "states" and path[2] == "with" and node.is_key:
        state = m.states.get(str(path[1]))
        spec = specs.get(state.do) if isinstance(state, CallState) else None
        param = spec.params.get(node.text) if spec else None
        if param is not None:
            return (
                f"param **{param.name}** of `{spec.name if spec else ''}`: {param.type}"
                + _default(param.required, param.default)
                + (f"\n\n{param.doc}" if param.doc else "")
            )
    return None


def _state(machine: MachineFile, name: str, specs: dict[str, BehaviourSpec]) -> str | None:
    state = machine.model.states.get(name)
    if state is None:
        return None
    if isinstance(state, ChoiceState):
        return f"state **{name}**: a choice of {len(state.choose)} branches"
    if isinstance(state, ParallelState):
        regions = ", ".join(f"{r} (`{reg.do}`)" for r, reg in state.parallel.items())
        return f"state **{name}**: parallel regions {regions}" + _arcs(state.on)
    spec = specs.get(state.do)
    what = f"calls `{state.do}`" + (f" ({spec.kind})" if spec else "")
    return f"state **{name}**: {what}" + _arcs(state.on) + (f"\n\n{state.doc}" if state.doc else "")


def _arcs(on: dict[str, str]) -> str:
    return "".join(f"\n- on `{event}` → `{target}`" for event, target in on.items()) if on else ""
