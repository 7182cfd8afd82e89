"""One name, several machines: the key each machine of a run is known by, and calls rewritten to it.

A machine's key is its name, unless a primitive of the run has that name or another machine took it
first (the run's own files first, then user files, then library files, each in the order they were
loaded); then it is `name@folder` (the folder it lies in), numbered if that is taken too.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from hfsm.model import CallState, Machine, ParallelState


def assign_keys(files: list[tuple[Path, bool]], roots: list[Path], primitives: list[str]) -> dict[Path, str]:
    """Each machine file's key: `files` are (resolved path, found in a library only), in load order."""

    def rank(file: tuple[Path, bool]) -> int:
        return 0 if file[0] in roots else 2 if file[1] else 1

    taken = set(primitives)
    keys: dict[Path, str] = {}
    for path, _ in sorted(files, key=rank):  # sorted is stable: load order within a rank
        key = path.stem
        n = 1
        while key in taken:
            key = f"{path.stem}@{path.parent.name}{n if n > 1 else ''}"
            n += 1
        taken.add(key)
        keys[path] = key
    return keys


def rewrite_calls(model: Machine, to_key: Mapping[str, str]) -> Machine:
    """The machine with each `do:` naming a machine replaced by that machine's key."""
    if all(name == key for name, key in to_key.items()):
        return model
    states = {}
    for name, state in model.states.items():
        if isinstance(state, CallState) and state.do in to_key:
            state = state.model_copy(update={"do": to_key[state.do]})
        elif isinstance(state, ParallelState):
            regions = {
                r: reg.model_copy(update={"do": to_key[reg.do]}) if reg.do in to_key else reg
                for r, reg in state.parallel.items()
            }
            state = state.model_copy(update={"parallel": regions})
        states[name] = state
    return model.model_copy(update={"states": states})
