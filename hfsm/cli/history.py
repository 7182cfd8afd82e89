"""`--history FILE`: the top machine's `history` param on a flag of its own, and the values of the
top machine's params checked by the checks plug-ins register (`Registry.check_param`) before
anything runs: a bad history file is exit 2, every problem at its line and column."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from hfsm.cli.params import parse_params
from hfsm.errors import Finding, UsageError, UserError
from hfsm.library import MachineFile
from hfsm.registry import Registry
from hfsm.spec import type_ok

PARAM = "history"


def top_params(
    pairs: list[str], history: Path | None, top: MachineFile, registry: Registry
) -> dict[str, Any]:
    """The top machine's params from `--param` pairs and `--history`, each value checked."""
    preset = {} if history is None else {PARAM: _history(pairs, history, top)}
    params = parse_params(pairs, top.model, top.name, top.doc, preset)
    check_values(params, top, registry)
    return params


def _history(pairs: list[str], history: Path, top: MachineFile) -> str:
    param = top.model.params.get(PARAM)
    if param is None:
        takes = ", ".join(top.model.params) or "nothing"
        message = (f"--history: '{top.name}' has no param '{PARAM}' to take the history file "
                   f"('{top.name}' takes: {takes})")
        raise UserError([_finding(top, ("params",), "E302", message)])
    if any(pair.partition("=")[0] == PARAM for pair in pairs):
        raise UsageError(f"--history and --param {PARAM}=... both give the history file: give one")
    if not type_ok(str(history), param.type):
        message = f"--history: '{top.name}' takes {param.type} for '{PARAM}', not a file name"
        raise UserError([_finding(top, ("params", PARAM), "E306", message)])
    return str(history)


def check_values(params: dict[str, Any], top: MachineFile, registry: Registry) -> None:
    """Every problem the registered checks find in the values of the params they check."""
    found = []
    for name, check in sorted(registry.param_checks.items()):
        if name in top.model.params and name in params:
            found += [Finding(file, line, col, "E340", f"{message} (param '{name}' of '{top.name}')")
                      for file, line, col, message in check(params[name])]
    if found:
        raise UserError(found)


def _finding(top: MachineFile, path: tuple[str, ...], code: str, message: str) -> Finding:
    return top.doc.finding(path, code, message, key=True)
