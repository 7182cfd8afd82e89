"""Load, check and compile: the one path from files on disk to a runnable program."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from hfsm import salvage
from hfsm.checks import enforce, run_checks
from hfsm.errors import Finding, UserError
from hfsm.library import Library, MachineFile
from hfsm.model import state_calls
from hfsm.registry import Registry
from hfsm.world import NO_INPUTS, InputSpec
from hfsm.yamlio import Parse, collector_paused, parse_text


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
    world: str | None = None,
    world_inputs: Mapping[str, Mapping[str, InputSpec]] | None = None,
) -> Loaded:
    """Read the files and all they call, run every check; raise UserError on any error.

    `world_inputs` (each world's declared inputs, by world name) lets the checks refuse an `in.x`
    that the run's world (`world`, else the one the machines need) does not declare; without it,
    inputs are not checked. The garbage collector is paused meanwhile: loading builds many objects
    and frees few, and the collector's passes over them made a large machine's load grow faster than
    its size.
    """
    for path in paths:
        try:
            path.resolve()
        except (RuntimeError, OSError) as exc:  # a symlink loop
            raise UserError([Finding(str(path), 1, 1, "E105", f"cannot read the file: {exc}")]) from None
    with collector_paused():
        return _load(paths, libs or [], registry, strict, world, world_inputs)


def world_of(machines: Mapping[str, MachineFile], registry: Registry, asked: str | None = None) -> str:
    """The run's world: the one asked for, else the first one a called primitive needs, else none."""
    if asked is not None:
        return asked
    return next(iter(worlds_needed(machines, registry)), "none")


def worlds_needed(machines: Mapping[str, MachineFile], registry: Registry) -> list[str]:
    """The worlds of the primitives the machines call (a parallel state calls its regions')."""
    called = {
        do for mf in machines.values() for n, s in mf.model.states.items() for _, do in state_calls(n, s)
    }
    return sorted({p.spec.world for p in registry if p.spec.world and p.spec.name in called})


def _load(
    paths: list[Path],
    libs: list[Path],
    registry: Registry | None,
    strict: bool,
    world: str | None,
    world_inputs: Mapping[str, Mapping[str, InputSpec]] | None,
) -> Loaded:
    library, roots, findings = check_files(paths, libs, registry, world, world_inputs)
    warnings = enforce(findings, strict=strict)
    return Loaded(library, roots, warnings)


def check_files(
    paths: list[Path],
    libs: list[Path],
    registry: Registry | None,
    world: str | None = None,
    world_inputs: Mapping[str, Mapping[str, InputSpec]] | None = None,
    texts: dict[Path, str] | None = None,
    parse: Parse = parse_text,
) -> tuple[Library, list[MachineFile], list[Finding]]:
    """Read the files and all they call and run every check: every finding, errors and warnings.
    `texts`: files' texts as an editor holds them (by resolved path), read instead of the disk's;
    `parse`: as `hfsm.yamlio.parse_text` (an editor's server reads again only what changed)."""
    registry = registry if registry is not None else Registry()
    library = Library.for_file(paths[0], libs, registry, texts, parse)
    for extra in paths[1:]:
        library.add_user_folder(extra.resolve().parent)
    roots = library.load(paths)
    inputs = None
    if world_inputs is not None:
        inputs = world_inputs.get(world_of(library.machines, registry, world), NO_INPUTS)
    docs = {m.doc.file: m.doc for m in library.machines.values()}
    removed = dict(library.removed)
    findings = salvage.consequences(run_checks(library.machines, registry, inputs), docs, removed)
    return library, roots, sorted(set(library.findings + findings))
