"""Load, check and compile: the one path from files on disk to a runnable program."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from hfsm.checks import enforce, run_checks
from hfsm.errors import Finding
from hfsm.library import Library, MachineFile
from hfsm.registry import Registry
from hfsm.yamlio import collector_paused


@dataclass
class Loaded:
    library: Library
    roots: list[MachineFile]
    warnings: list[Finding]

    @property
    def machines(self) -> dict[str, MachineFile]:
        return self.library.machines


def load(
    paths: list[Path],
    *,
    libs: list[Path] | None = None,
    registry: Registry | None = None,
    strict: bool = False,
) -> Loaded:
    """Read the files and all they call, run every check; raise UserError on any error.

    The garbage collector is paused meanwhile: loading builds many objects and frees few, and the
    collector's passes over them made a large machine's load grow faster than its size.
    """
    with collector_paused():
        return _load(paths, libs or [], registry, strict)


def _load(paths: list[Path], libs: list[Path], registry: Registry | None, strict: bool) -> Loaded:
    registry = registry if registry is not None else Registry()
    library = Library.for_file(paths[0], libs, registry)
    for extra in paths[1:]:
        if extra.resolve().parent not in library.search:
            library.search.insert(1, extra.resolve().parent)
    roots = library.load(paths)
    warnings = enforce(library.findings + run_checks(library.machines, registry), strict=strict)
    return Loaded(library, roots, warnings)
