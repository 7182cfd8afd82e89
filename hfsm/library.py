"""Finding and loading machine files by name, where the calling file lies (docs/REFERENCE.md).

A name in `do:` is looked up from the file that writes it. A *user* file (the run's own, or one
found in a user folder: the top file's, a `--lib` folder) looks in its own folder, the top file's
folder, each `--lib` folder, then the libraries (the project's `machines/`, then plug-ins'), then
the primitives. A *library* file looks in its own library, the other libraries, then the
primitives, never in a user folder. So one name may mean two machines in one run (a user's
`hold.yaml` and the primitive `hold`): each machine is known by a key, its name unless another
machine or a primitive of the run has that name, and each file's `do:` is rewritten to the key it
resolves to (`shadow.py`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from pathlib import Path

from hfsm import located, salvage
from hfsm.builtins import BUILTINS
from hfsm.errors import Finding, Severity, UserError
from hfsm.model import Machine, state_calls
from hfsm.names import NAME_RULE, did_you_mean, is_name
from hfsm.registry import Registry
from hfsm.shadow import assign_keys, rewrite_calls
from hfsm.yamlio import Document, Parse, Path_, parse_text, read_mapping

PROJECT_MACHINES = Path(__file__).resolve().parent.parent / "machines"
SUFFIXES = (".yaml", ".yml")


@dataclass(frozen=True)
class MachineFile:
    name: str  # how the run knows it: the file's stem, unless another machine of the run has it
    path: Path
    doc: Document
    model: Machine
    library: bool = False  # found in a library folder only: it never looks in user folders

    @property
    def stem(self) -> str:
        return self.path.stem


def shown(path: Path) -> Path:
    """A path as users should read it: relative to the working folder when inside it."""
    try:
        return path.resolve().relative_to(Path.cwd())
    except ValueError:
        return path


def check_stem(path: Path) -> None:
    """A file whose stem is no machine name is refused before it is read (E203, naming the file)."""
    if not is_name(path.stem):
        raise UserError([Finding(str(shown(path)), 1, 1, "E203", stem_problem(path))])


def load_machine_file(path: Path) -> MachineFile:
    check_stem(path)
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
    path: Path, text: str | None = None, parse: Parse = parse_text
) -> tuple[MachineFile | None, list[Finding], set[Path_]]:
    """The machine of a file, built from its well-formed part; every problem found on the way; the
    states left out. Raises UserError only when nothing of it can be read (its YAML is broken)."""
    if not is_name(path.stem):
        raise UserError([Finding(str(shown(path)), 1, 1, "E203", stem_problem(path))])
    problems: list[Finding] = []
    doc = read_mapping(shown(path), "a machine", text=text, kept=problems, parse=parse)
    model, findings, removed = salvage.validate(Machine, doc)
    machine = MachineFile(path.stem, path, doc, model) if model is not None else None
    return machine, problems + findings, removed


def _unique(folders: list[Path]) -> list[Path]:
    return [p for i, p in enumerate(folders) if p not in folders[:i]]


class Library:
    """The machines of one run: the top file's, and every machine they call, at any depth."""

    def __init__(
        self,
        search: list[Path],
        registry: Registry,
        libraries: list[Path] | None = None,
        texts: dict[Path, str] | None = None,
        parse: Parse = parse_text,
    ) -> None:
        self.texts = texts or {}  # files' texts as an editor holds them, by resolved path
        self.parse = parse
        self.removed: dict[str, set[Path_]] = {}  # by file: states left out, their schema being wrong
        self.users = _unique([p for p in search if libraries is None or p not in libraries])
        self.libraries = _unique(libraries or [])
        self.registry = registry
        self.machines: dict[str, MachineFile] = {}
        self.findings: list[Finding] = []
        self._by_path: dict[Path, MachineFile] = {}
        self._calls: dict[Path, dict[str, Path]] = {}  # a file's callee names -> machine paths
        self._failed: set[Path] = set()  # files that could not be loaded, reported once

    @property
    def unloaded(self) -> set[Path]:
        """The files that were called but could not be loaded (resolved paths)."""
        return set(self._failed)

    @property
    def search(self) -> list[Path]:
        """Every folder, in a user file's order (after its own folder)."""
        return _unique([*self.users, *self.libraries])

    @classmethod
    def for_file(
        cls,
        top: Path,
        libs: list[Path],
        registry: Registry,
        texts: dict[Path, str] | None = None,
        parse: Parse = parse_text,
    ) -> Library:
        libraries = [PROJECT_MACHINES, *(p.resolve() for p in registry.machine_folders)]
        users = [top.resolve().parent, *(p.resolve() for p in libs)]
        return cls(users, registry, [p for p in libraries if p not in users], texts, parse)

    def add_user_folder(self, folder: Path) -> None:
        """Another root's folder (a test run of several files): a user folder after the top file's."""
        if folder not in self.users:
            self.users.insert(1, folder)
            self.libraries = [p for p in self.libraries if p != folder]

    def find(self, name: str, folders: list[Path] | None = None) -> Path | None:
        for folder in self.search if folders is None else folders:
            for suffix in SUFFIXES:
                candidate = folder / f"{name}{suffix}"
                if candidate in self.texts or candidate.is_file():
                    return candidate
        return None

    def known_names(self, folders: list[Path] | None = None) -> set[str]:
        names = set(BUILTINS) | set(self.registry.names())
        for folder in self.search if folders is None else folders:
            if folder.is_dir():
                names.update(p.stem for p in folder.iterdir() if p.suffix in SUFFIXES)
        return names

    def folders_of(self, machine: MachineFile) -> list[Path]:
        """Where the names a file calls are looked for, in order (docs/REFERENCE.md)."""
        own = machine.path.resolve().parent
        if machine.library:
            return _unique([own, *self.libraries])
        return _unique([own, *self.users, *self.libraries])

    def load(self, roots: list[Path]) -> list[MachineFile]:
        """Load the roots and everything they call; problems go to `findings`."""
        top = [self._add(path, library=False) for path in roots]
        pending = [m for m in top if m]
        done: set[Path] = set()
        while pending:
            machine = pending.pop()
            path = machine.path.resolve()
            if path in done:
                continue
            done.add(path)
            calls = self._calls.setdefault(path, {})
            for callee in self._callees(machine):
                found = self._resolve(machine, callee)
                if found is not None:
                    calls[callee] = found.path.resolve()
                    pending.append(found)
        self._finish([m.path.resolve() for m in top if m])
        return [self._by_path[m.path.resolve()] for m in top if m]

    def _add(self, path: Path, *, library: bool) -> MachineFile | None:
        resolved = path.resolve()
        existing = self._by_path.get(resolved)
        if existing is not None or resolved in self._failed:
            return existing
        try:
            salvaged, findings, removed = salvage_machine_file(path, self.texts.get(resolved), self.parse)
        except UserError as err:
            self.findings.extend(err.findings)
            self._failed.add(resolved)
            return None
        self.findings.extend(findings)
        if salvaged is None:
            self._failed.add(resolved)
            return None
        machine = replace(salvaged, library=library)
        if removed:
            self.removed[machine.doc.file] = removed
        if not self._check_name(machine):
            self._failed.add(resolved)
            return None  # it takes a built-in's name: reported once, then left out
        self._by_path[resolved] = machine
        return machine

    def _check_name(self, machine: MachineFile) -> bool:
        """Report a bad name; False when the machine takes a built-in's name."""
        if machine.model.name is not None and machine.model.name != machine.stem:
            message = f"name '{machine.model.name}' must equal the file's stem '{machine.stem}'"
            self.findings.append(machine.doc.finding(("name",), "E203", message))
        if machine.stem in BUILTINS:
            message = f"machine '{machine.stem}' takes the name of a built-in behaviour"
            self.findings.append(machine.doc.finding((), "E319", message))
            return False
        return True

    @staticmethod
    def _callees(machine: MachineFile) -> list[str]:
        names = {do for n, s in machine.model.states.items() for _, do in state_calls(n, s)}
        return sorted(n for n in names if n not in BUILTINS)

    def _resolve(self, caller: MachineFile, name: str) -> MachineFile | None:
        """The machine `name` means in `caller`'s file; None for a primitive or an unknown name."""
        folders = self.folders_of(caller)
        path = self.find(name, folders)
        if path is not None:
            return self._add(path, library=path.resolve().parent not in self.users)
        owners = self.registry.clashes.get(name)
        if owners:
            message = f"'{name}' is a primitive of two plug-ins, '{owners[0]}' and '{owners[1]}'"
            self._report(caller, name, "E350", message)
        elif name in self.registry:
            return None
        elif name in self.registry.elsewhere:
            world = self.registry.elsewhere[name]
            message = f"'{name}' is a primitive of --world {world}, not of this run's world"
            self._report(caller, name, "E300", message)
        else:
            hint = did_you_mean(name, self.known_names(folders))
            self._report(caller, name, "E300", f"unknown behaviour '{name}'{hint}")
        return None

    def _report(self, caller: MachineFile, name: str, code: str, message: str) -> None:
        for state_name, state in caller.model.states.items():
            for where, do in state_calls(state_name, state):
                if do == name:
                    self.findings.append(caller.doc.finding(where, code, message))

    def _finish(self, roots: list[Path]) -> None:
        """Keys given, calls rewritten to them, shadowing warned of; `machines` filled by key."""
        files = [(path, m.library) for path, m in self._by_path.items()]
        keys = assign_keys(files, roots, self.registry.names())
        for path, machine in self._by_path.items():
            to_key = {name: keys[target] for name, target in self._calls.get(path, {}).items()}
            model = rewrite_calls(machine.model, to_key)
            self._by_path[path] = replace(machine, name=keys[path], model=model)
        self.machines = {m.name: m for m in self._by_path.values()}
        self.findings.extend(self._shadowing())

    def _shadowing(self) -> list[Finding]:
        """A user machine named like a library machine or a primitive: a warning naming both."""
        found = []
        for machine in self._by_path.values():
            if machine.library:
                continue
            name = machine.stem
            shadowed = self.find(name, self.libraries)
            if shadowed is not None and shadowed.resolve() != machine.path.resolve():
                what = f"the library machine {shown(shadowed)}"
            elif name in self.registry or name in self.registry.elsewhere:
                what = f"the primitive '{name}'"
            else:
                continue
            message = (
                f"machine '{name}' ({shown(machine.path)}) shadows {what} for user files; "
                "library files still call the library's"
            )
            f = machine.doc.finding((), "W406", message)
            found.append(Finding(f.file, f.line, f.col, f.code, f.message, Severity.WARNING))
        return found
