"""Where a run-time error happened, in the files: the state (or the expression in it) that its path
names, as a finding with the agent and the time, so it prints like a check's error."""

from __future__ import annotations

import re
from collections.abc import Mapping
from pathlib import Path

from hfsm.errors import Finding
from hfsm.library import MachineFile
from hfsm.model import CallState, ParallelState
from hfsm.runtime.agent import CALLEE
from hfsm.yamlio import Path_

_QUOTED = re.compile(r"in '(.+?)'(?::|$)")


def locate(
    machines: Mapping[str, MachineFile],
    top: str,
    origin: str,
    message: str,
    agent: str,
    time: float,
    where: Path_ = (),
) -> Finding | None:
    """The finding of an error met by `agent` at `time` in the state at path `origin` (`top/s/...`):
    at the expression that failed when `where` is known: its path in that state's machine file, or
    after CALLEE, in the file of the machine run at `origin` (its own `outputs:` or `timer:`)."""
    found, runs = _state(machines, top, origin.split("/")[1:])
    if where[:1] == (CALLEE,):
        at = _expression(runs, where[1:]) if runs is not None else None
        if runs is not None and at is not None:
            return Finding(runs.doc.file, *at, "", f"{agent} at t={time:g} s: {message}")
        where = ()
    if found is None:
        return None
    machine, path = found
    line, col = machine.doc.pos(path, key=True)
    at = _expression(machine, where) if where else None
    if at is not None:
        line, col = at
    else:
        expression = _QUOTED.search(message)
        if expression is not None:
            line, col = _find_text(machine.doc.file, expression.group(1), line, col)
    return Finding(machine.doc.file, line, col, "", f"{agent} at t={time:g} s: {message}")


def _expression(machine: MachineFile, where: Path_) -> tuple[int, int] | None:
    """Where the expression at `where` is written: the value's position, or its `${` (the n-th of
    the string, when `where` ends with n past the string)."""
    doc, value, n = machine.doc, machine.doc.data, 0
    for i, part in enumerate(where):
        if _has(value, part):
            value = value[part]
        elif isinstance(value, str) and isinstance(part, int) and i == len(where) - 1:
            n, where = part, where[:i]
            break
        else:
            return None
    start = doc.values.get(tuple(where))
    if start is None:
        return None
    if not isinstance(value, str) or "${" not in value:
        return start
    lines = (doc.text or "").splitlines()
    line, col = start
    for number in range(line - 1, len(lines)):
        text, begin = lines[number], (col - 1 if number == line - 1 else 0)
        while (at := text.find("${", begin)) >= 0:
            if n == 0:
                return number + 1, at + 1
            n, begin = n - 1, at + 2
    return start


def _has(value: object, part: str | int) -> bool:
    if isinstance(value, dict):
        return part in value
    return isinstance(value, list) and isinstance(part, int) and 0 <= part < len(value)


def _state(
    machines: Mapping[str, MachineFile], top: str, names: list[str]
) -> tuple[tuple[MachineFile, Path_] | None, MachineFile | None]:
    """The machine file and the path of the last state along `names` (states, regions, states...),
    and the machine that state (or, for no names, the run) runs."""
    machine = machines.get(top)
    found: tuple[MachineFile, Path_] | None = None
    i = 0
    while machine is not None and i < len(names):
        state = machine.model.states.get(names[i])
        if state is None:
            return found, None
        found = (machine, ("states", names[i]))
        callee = None
        if isinstance(state, CallState):
            callee, i = state.do, i + 1
        elif isinstance(state, ParallelState) and i + 1 < len(names) and names[i + 1] in state.parallel:
            region = names[i + 1]
            found = (machine, ("states", names[i], "parallel", region))
            callee, i = state.parallel[region].do, i + 2
        else:
            i += 1
        machine = machines.get(callee) if callee is not None else None
    return found, machine


def _find_text(file: str, text: str, line: int, col: int) -> tuple[int, int]:
    """The first place at or after (line, col) where `text` is written; (line, col) if nowhere."""
    try:
        lines = Path(file).read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError):
        return line, col
    for n in range(line - 1, len(lines)):
        at = lines[n].find(text)
        if at >= 0:
            return n + 1, at + 1
    return line, col
