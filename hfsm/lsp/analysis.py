"""The open documents and what the checks find in them, with the whole library in view.

A machine file is checked exactly as `hfsm-run --check FILE` checks it (the same loading, the same
checks, the same world's inputs), reading open documents' texts instead of the disk's; a test file
(`*.test.yaml`) as `hfsm-test` checks it. What was last read well of a document is kept, so that
hover, completion and navigation still work while its YAML is half-typed.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from hfsm import plugins
from hfsm.checks.context import CheckContext
from hfsm.cli.quiet import stdout_to_stderr
from hfsm.errors import Finding, UserError
from hfsm.library import PROJECT_MACHINES, SUFFIXES, Library, MachineFile, shown
from hfsm.load import check_files, world_of
from hfsm.lsp.reparse import Reparser
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec
from hfsm.world import NO_INPUTS, WORLDS_GROUP, InputSpec, NullWorld
from hfsm.yamlio import Document, collector_paused, read_mapping


def _disk_text(path: Path) -> str | None:
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None


def is_test_file(path: Path) -> bool:
    return path.name.endswith((".test.yaml", ".test.yml"))


@dataclass
class Settings:
    """What `hfsm-run --check` takes from its command line: more machine folders, the world."""

    libs: list[Path] = field(default_factory=list)
    world: str | None = None


@dataclass
class Analysis:
    """One check of one document, and what it read."""

    path: Path
    findings: list[Finding]  # of every file the check read
    library: Library | None
    registry: Registry
    inputs: Mapping[str, InputSpec] | None
    doc: Document | None = None  # a test file's, as read (None: it could not be)

    @property
    def machine(self) -> MachineFile | None:
        if self.library is None:
            return None
        found = self.library.machines.get(self.path.stem)
        return found if found is not None and found.path.resolve() == self.path else None

    @cached_property
    def specs(self) -> dict[str, BehaviourSpec]:
        machines = self.library.machines if self.library is not None else {}
        return CheckContext(machines, self.registry).specs

    def known_behaviours(self) -> list[str]:
        names = set(self.specs)
        if self.library is not None:
            names |= self.library.known_names()
        return sorted(names)

    def files(self) -> set[Path]:
        """The files this check read: the document and every machine it calls, at any depth (those
        that could not be loaded too)."""
        if self.library is None:
            return {self.path}
        loaded = {m.path.resolve() for m in self.library.machines.values()}
        return {self.path} | loaded | self.library.unloaded


class Workspace:
    """The documents an editor has open, their texts, and their latest checks."""

    def __init__(self, settings: Settings | None = None, registry: Registry | None = None) -> None:
        self.settings = settings or Settings()
        self.texts: dict[Path, str] = {}
        self.analyses: dict[Path, Analysis] = {}
        self.last_good: dict[Path, MachineFile] = {}  # the latest machine read of each document
        self.last_tests: dict[Path, Document] = {}  # the latest test file read of each document
        self._registry = registry
        self.reparser = Reparser()  # a changed document read again from what changed

    @cached_property
    def registry(self) -> Registry:
        if self._registry is not None:
            return self._registry
        with stdout_to_stderr():  # a plug-in's banner must not reach the protocol's stream
            return Registry.discover()

    @cached_property
    def world_inputs(self) -> dict[str, Mapping[str, InputSpec]]:
        found: dict[str, Mapping[str, InputSpec]] = {"none": NullWorld().inputs()}
        with stdout_to_stderr():
            for ep, cls in plugins.load_each(WORLDS_GROUP, lambda ep, obj: None):
                ok, factory = plugins.run_hook(ep, cls)
                if ok:
                    found[factory.name] = factory.inputs()
        return found

    def set_text(self, path: Path, text: str) -> list[Path]:
        """A document opened or changed: the open documents to check again (it and its callers)."""
        path = path.resolve()
        before = self.texts.get(path)
        self.texts[path] = text
        if text == (before if before is not None else _disk_text(path)):
            return [path]  # what its callers read has not changed
        return [path, *(p for p, a in self.analyses.items() if p != path and path in a.files())]

    def close(self, path: Path) -> None:
        path = path.resolve()
        self.texts.pop(path, None)
        self.analyses.pop(path, None)
        self.last_good.pop(path, None)
        self.last_tests.pop(path, None)

    def analyse(self, path: Path) -> Analysis:
        path = path.resolve()
        with collector_paused():  # a check builds many objects and frees few, as `load` does
            analysis = self._test_file(path) if is_test_file(path) else self._machine_file(path)
        self.analyses[path] = analysis
        if analysis.machine is not None:
            self.last_good[path] = analysis.machine
        if analysis.doc is not None:
            self.last_tests[path] = analysis.doc
        return analysis

    def _machine_file(self, path: Path) -> Analysis:
        registry = self.registry
        if self.settings.world is not None:
            registry = registry.for_world(self.settings.world)
        try:
            library, _, findings = check_files(
                [path],
                self.settings.libs,
                registry,
                self.settings.world,
                self.world_inputs,
                self.texts,
                self.reparser.parse,
            )
        except UserError as err:
            return Analysis(path, err.findings, None, registry, None)
        world = world_of(library.machines, registry, self.settings.world)
        return Analysis(path, findings, library, registry, self.world_inputs.get(world, NO_INPUTS))

    def _test_file(self, path: Path) -> Analysis:
        from hfsm.testing.check import full_registry, read_test_file

        registry = full_registry()
        findings: list[Finding] = []
        try:
            read_test_file(path, registry, text=self.texts.get(path))
        except UserError as err:
            findings = err.findings
        try:
            doc = read_mapping(shown(path), "a behaviour test", text=self.texts.get(path))
        except UserError:
            return Analysis(path, findings, None, registry, None)
        return Analysis(path, findings, self._tested(path, doc, registry), registry, None, doc)

    def _tested(self, path: Path, doc: Document, registry: Registry) -> Library:
        """The machines a test file tests, and all they call, found as `hfsm-test` finds them."""
        here = path.parent
        data = doc.data if isinstance(doc.data, dict) else {}
        settings = [data, *(c for c in (data.get("tests") or {}).values() if isinstance(c, dict))]
        libs = [here / lib for s in settings for lib in (s.get("lib") or []) if isinstance(lib, str)]
        library = Library([here, *libs, PROJECT_MACHINES], registry, texts=self.texts)
        found = []
        for name in (s.get("machine") for s in settings):
            if isinstance(name, str):
                file = here / name if "/" in name or name.endswith(SUFFIXES) else library.find(name)
                if file is not None and (file.resolve() in self.texts or file.is_file()):
                    found.append(file)
        library.load(list(dict.fromkeys(found)))
        return library
