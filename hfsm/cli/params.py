"""`--param k=v`: values read as YAML 1.2 flow values, checked against the top machine's params."""

from __future__ import annotations

from typing import Any

from hfsm.errors import UsageError, UserError
from hfsm.model import Machine
from hfsm.names import did_you_mean
from hfsm.spec import coerce, type_ok
from hfsm.yamlio import parse_text


def parse_params(pairs: list[str], machine: Machine, name: str) -> dict[str, Any]:
    given: dict[str, Any] = {}
    problems: list[str] = []
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep:
            problems.append(f"--param {pair!r}: write NAME=VALUE")
            continue
        param = machine.params.get(key)
        if param is None:
            hint = (
                did_you_mean(key, machine.params)
                or f" ('{name}' takes: {', '.join(machine.params) or 'nothing'})"
            )
            problems.append(f"--param {key}: '{name}' has no param '{key}'{hint}")
            continue
        try:
            value = parse_text(text, "--param").data if text.strip() else ""
        except UserError:
            problems.append(f"--param {key}: cannot read {text!r} as a YAML flow value")
            continue
        if not type_ok(value, param.type):
            problems.append(f"--param {key}: '{name}' takes {param.type}, not {value!r}")
            continue
        given[key] = coerce(value, param.type)
    for key, param in machine.params.items():
        if key not in given:
            if param.required:
                problems.append(f"'{name}' needs --param {key}=VALUE ({param.type})")
            else:
                given[key] = param.default
    if problems:
        raise UsageError("\n".join(problems))
    return given
