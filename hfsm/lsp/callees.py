"""Errors in the machines a document calls, shown at the document's `do:`.

`hfsm-run --check FILE` prints a callee's errors at their own file, line and column, and so does the
server, in the callee's document. An editor shows only the open document's diagnostics, though, so
the caller gets one more at each `do: NAME` whose machine (or a machine it calls, at any depth) has
errors, or does not load: "'NAME' has N errors: first at FILE:LINE:COL: ...", with every one of them
as the diagnostic's related information (LSP `relatedInformation`), each at its own place. It is
not a finding of its own (no code): the findings are the callee's, already reported where they are.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from hfsm.errors import Finding, Severity
from hfsm.library import Library, MachineFile
from hfsm.lsp.analysis import Analysis
from hfsm.model import state_calls


@dataclass(frozen=True)
class CalleeErrors:
    at: Finding  # in the caller's file, at the `do:` value
    name: str  # as the caller writes it
    errors: list[Finding]  # the callee's, and those of what it calls: its own first


def callee_errors(analysis: Analysis) -> list[CalleeErrors]:
    machine, library = analysis.machine, analysis.library
    if machine is None or library is None:
        return []
    errors: dict[Path, list[Finding]] = {}
    for finding in analysis.findings:
        if finding.severity is Severity.ERROR:
            errors.setdefault(Path(finding.file).resolve(), []).append(finding)
    errors.pop(analysis.path, None)
    if not errors:
        return []
    found = []
    for name, state in machine.model.states.items():
        for where, key in state_calls(name, state):
            written = _written(machine, where, key)
            path = _file_of(library, machine, key, written)
            if path is None:
                continue
            mine = [f for p in _reach(library, path) for f in errors.get(p, [])]
            if not mine:
                continue
            first = mine[0]
            s = "s" if len(mine) > 1 else ""
            message = (
                f"'{written}' has {len(mine)} error{s}: first at {first.file}:{first.line}:{first.col}: "
                f"{first.message}"
            )
            found.append(CalleeErrors(machine.doc.finding(where, "", message), written, mine))
    return found


def _written(machine: MachineFile, where: tuple[str | int, ...], key: str) -> str:
    value: object = machine.doc.data
    for part in where:
        value = value.get(part) if isinstance(value, dict) else None
    return value if isinstance(value, str) else key


def _file_of(library: Library, caller: MachineFile, key: str, written: str) -> Path | None:
    """The file a `do:` calls: a loaded machine's, else the file found by its name (one that could
    not be loaded); None for a built-in or a primitive."""
    loaded = library.machines.get(key)
    if loaded is not None:
        return loaded.path.resolve()
    found = library.find(written, library.folders_of(caller))
    return found.resolve() if found is not None else None


def _reach(library: Library, start: Path) -> list[Path]:
    """The file and the files of every machine it calls, at any depth: it first."""
    by_path = {m.path.resolve(): m for m in library.machines.values()}
    order, pending = [start], [start]
    while pending:
        machine = by_path.get(pending.pop())
        if machine is None:
            continue
        for name, state in machine.model.states.items():
            for where, key in state_calls(name, state):
                path = _file_of(library, machine, key, _written(machine, where, key))
                if path is not None and path not in order:
                    order.append(path)
                    pending.append(path)
    return order
