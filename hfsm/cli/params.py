"""`--param k=v`: values read as YAML 1.2 flow values, checked against the top machine's params."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hfsm.errors import Finding, UsageError, UserError
from hfsm.model import Machine
from hfsm.names import did_you_mean
from hfsm.spec import coerce, shown, type_ok
from hfsm.yamlio import Document, parse_text


class _Problems:
    """Problems with the params; one about a declared param points at its declaration in `doc`."""

    def __init__(self, doc: Document | None) -> None:
        self.doc = doc
        self.usage: list[str] = []
        self.found: list[Finding] = []

    def add(self, path: tuple[str, ...], code: str, message: str) -> None:
        if self.doc is None:
            self.usage.append(message)
        else:
            self.found.append(self.doc.finding(path, code, message, key=True))

    def raise_any(self) -> None:
        if self.usage:
            raise UsageError("\n".join([*self.usage, *(f.format() for f in sorted(self.found))]))
        if self.found:
            raise UserError(self.found)


def parse_params(
    pairs: list[str],
    machine: Machine,
    name: str,
    doc: Document | None = None,
    preset: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """The top machine's params from `--param K=V` pairs, and `preset` values given by other flags
    (already checked), every problem at once."""
    given: dict[str, Any] = dict(preset or {})
    problems = _Problems(doc)
    tried: set[str] = set()  # a param given wrongly is reported as such, not also as missing
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep:
            problems.usage.append(f"--param {pair!r}: write NAME=VALUE")
            continue
        param = machine.params.get(key)
        tried.add(key)
        if param is None:
            hint = (
                did_you_mean(key, machine.params)
                or f" ('{name}' takes: {', '.join(machine.params) or 'nothing'})"
            )
            problems.add(("params",), "E302", f"--param {key}: '{name}' has no param '{key}'{hint}")
            continue
        try:
            value = parse_text(text, "--param").data if text.strip() else ""
        except UserError:
            problems.add(("params", key), "E306", f"--param {key}: cannot read {text!r} as a YAML flow value")
            continue
        if not type_ok(value, param.type):
            problems.add(
                ("params", key), "E306", f"--param {key}: '{name}' takes {param.type}, not {shown(value)}"
            )
            continue
        given[key] = coerce(value, param.type)
    for key, param in machine.params.items():
        if key not in given and param.required and key not in tried:
            problems.add(("params", key), "E307", f"'{name}' needs --param {key}=VALUE ({param.type})")
        elif key not in given:
            given[key] = param.default
    problems.raise_any()
    return given
