"""Finding and loading machine files by name along the search path (docs/REFERENCE.md#hfsm-run)."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from hfsm import located, salvage
from hfsm.builtins import BUILTINS
from hfsm.errors import Finding, UserError
from hfsm.model import Machine, state_calls
from hfsm.names import NAME_RULE, did_you_mean, is_name
from hfsm.registry import Registry
from hfsm.yamlio import Document, Path_, read_mapping

PROJECT_MACHINES = Path(__file__).resolve().parent.parent / "machines"
SUFFIXES = (".yaml", ".yml")


@dataclass(frozen=True)
class MachineFile:
    name: str
    path: Path
    doc: Document
    model: Machine


def shown(path: Path) -> Path:
    """A path as users should read it: relative to the working folder when inside it."""
    try:
        return path.resolve().relative_to(Path.cwd())
    except ValueError:
        return path


def load_machine_file(path: Path) -> MachineFile:
    if not is_name(path.stem):
        raise UserError([Finding(str(shown(path)), 1, 1, "E203", stem_problem(path))])
    doc = read_mapping(shown(path), "a machine")
    model = located.validate(Machine, doc)
    return MachineFile(path.stem, path, doc, model)


def stem_problem(path: Path) -> str:
    """Why a file's stem cannot name a machine, with a name it could have."""
    better = re.sub(r"[^a-z0-9_]+", "_", path.stem.lower()).strip("_") or "machine"
    if not better[0].isalpha():
        better = "m_" + better
    return (f"the file name '{path.name}' does not make a machine name ({NAME_RULE}): "
            f"rename it, e.g. '{better}{path.suffix}'")


def salvage_machine_file(
    path: Path, text: str | None = None
) -> tuple[MachineFile | None, list[Finding], set[Path_]]:
    """The machine of a file, built from its well-formed part; every problem found on the way; the
    states left out. Raises UserError only when nothing of it can be read (its YAML is broken)."""
    problems: list[Finding] = []
    doc = read_mapping(shown(path), "a machine", text=text, kept=problems)
    model, findings, removed = salvage.validate(Machine, doc)
    machine = MachineFile(path.stem, path, doc, model) if model is not None else None
    return machine, problems + findings, removed


class Library:
    """The machines of one run: the top file's, and every machine they call, at any depth."""

    def __init__(self, search: list[Path], registry: Registry, texts: dict[Path, str] | None = None) -> None:
        self.search = [p for i, p in enumerate(search) if p not in search[:i]]
        self.registry = registry
        self.machines: dict[str, MachineFile] = {}
        self.findings: list[Finding] = []
        self.texts = texts or {}  # files' texts as an editor holds them, by resolved path
        self.removed: dict[str, set[Path_]] = {}  # by machine: states left out, their schema being wrong

    @classmethod
    def for_file(
        cls, top: Path, libs: list[Path], registry: Registry, texts: dict[Path, str] | None = None
    ) -> Library:
        plugins = [p.resolve() for p in registry.machine_folders]
        folders = [top.resolve().parent, *(p.resolve() for p in libs), *plugins, PROJECT_MACHINES]
        return cls(folders, registry, texts)

    def find(self, name: str) -> Path | None:
        for folder in self.search:
            for suffix in SUFFIXES:
                candidate = folder / f"{name}{suffix}"
                if candidate in self.texts or candidate.is_file():
                    return candidate
        return None

    def known_names(self) -> set[str]:
        names = set(BUILTINS) | set(self.registry.names())
        for folder in self.search:
            if folder.is_dir():
                names.update(p.stem for p in folder.iterdir() if p.suffix in SUFFIXES)
        return names

    def load(self, roots: list[Path]) -> list[MachineFile]:
        """Load the roots and everything they call; problems go to `findings`."""
        top = [self._add(path) for path in roots]
        pending = [m for m in top if m]
        while pending:
            machine = pending.pop()
            for callee in self._callees(machine):
                if callee not in self.machines:
                    found = self._resolve(machine, callee)
                    if found:
                        pending.append(found)
        return [m for m in top if m]

    def _add(self, path: Path) -> MachineFile | None:
        try:
            machine, findings, removed = salvage_machine_file(path, self.texts.get(path.resolve()))
        except UserError as err:
            self.findings.extend(err.findings)
            return None
        self.findings.extend(findings)
        if machine is None:
            return None
        if removed:
            self.removed[machine.name] = removed
        if not self._check_name(machine):
            return None  # it shadows a built-in or a primitive: reported once, then left out
        existing = self.machines.get(machine.name)
        if existing and existing.path.resolve() != path.resolve():
            self.findings.append(
                machine.doc.finding(
                    (), "E319", f"two machines are named '{machine.name}': also {existing.path}"
                )
            )
        self.machines[machine.name] = machine
        return machine

    def _check_name(self, machine: MachineFile) -> bool:
        """Report a bad name; False when the machine takes a built-in's or a primitive's name."""
        if machine.model.name is not None and machine.model.name != machine.name:
            message = f"name '{machine.model.name}' must equal the file's stem '{machine.name}'"
            self.findings.append(machine.doc.finding(("name",), "E203", message))
        if machine.name in BUILTINS or machine.name in self.registry:
            kind = "built-in behaviour" if machine.name in BUILTINS else "registered primitive"
            message = f"machine '{machine.name}' takes the name of a {kind}"
            self.findings.append(machine.doc.finding((), "E319", message))
            return False
        return True

    def _callees(self, machine: MachineFile) -> list[str]:
        names = {do for n, s in machine.model.states.items() for _, do in state_calls(n, s)}
        return sorted(n for n in names if n not in BUILTINS and n not in self.registry)

    def _resolve(self, caller: MachineFile, name: str) -> MachineFile | None:
        path = self.find(name)
        if path is not None:
            return self._add(path)
        world = self.registry.elsewhere.get(name)
        if world:
            message = f"'{name}' is a primitive of --world {world}, not of this run's world"
        else:
            message = f"unknown behaviour '{name}'{did_you_mean(name, self.known_names())}"
        for state_name, state in caller.model.states.items():
            for where, do in state_calls(state_name, state):
                if do == name:
                    self.findings.append(caller.doc.finding(where, "E300", message))
        return None
