"""A machine given by name on the command line (`hfsm-run move_furniture`, `hfsm-graph leader`): found
in the --lib folders and the installed plug-ins' machines, or refused with the closest name."""

from __future__ import annotations

from pathlib import Path

from hfsm.errors import UsageError
from hfsm.library import SUFFIXES, Library
from hfsm.names import did_you_mean, is_name
from hfsm.registry import Registry


def machine_path(given: Path, libs: list[Path], registry: Registry) -> Path:
    """`given` when it exists or is no name (the reader reports a missing file); else the machine of
    that name along the folders, else a UsageError with the closest machine name."""
    if given.exists() or not is_name(str(given)):
        return given
    folders = [*libs, *registry.machine_folders]
    found = Library(folders, registry).find(str(given))
    if found is not None:
        return found
    known = [p.stem for folder in [Path("."), *folders] if folder.is_dir()
             for p in folder.iterdir() if p.suffix in SUFFIXES]
    looked = ", ".join(str(f) for f in folders) or "no folder (give --lib DIR)"
    raise UsageError(f"'{given}' is no file here, nor a machine in {looked}{did_you_mean(str(given), known)}")
