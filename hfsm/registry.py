"""The primitives a run may call, found through the `hfsm.primitives` entry-point group."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any

from hfsm import plugins
from hfsm.primitive import Primitive

GROUP = "hfsm.primitives"
MACHINES_GROUP = "hfsm.machines"  # an entry point `module:function` returns a folder of machine files

Problem = tuple[str, int, int, str]
"""(file, line, column, message): a problem in a file a param names, 1-based."""
ParamCheck = Callable[[Any], list[Problem]]
"""A check of a value given to the top machine's param of that name, run before anything runs
(`hfsm-run`, `--check` too): e.g. the `history` file of TARARC's machines must be readable."""


class Registry:
    """Primitives by name, and checks of the top machine's params by name (`check_param`). A
    plug-in's entry point is a function `register(registry)`."""

    def __init__(self, primitives: Iterable[Primitive] = ()) -> None:
        self._by_name: dict[str, Primitive] = {}
        self.elsewhere: dict[str, str] = {}  # primitives left out: name -> the world they need
        self.machine_folders: list[Path] = []  # plug-ins' machines, searched after the project's
        self.clashes: dict[str, tuple[str, str]] = {}  # a primitive two plug-ins register: their names
        self.param_checks: dict[str, ParamCheck] = {}
        self.add(*primitives)

    def check_param(self, name: str, check: ParamCheck) -> None:
        """Check the value of the top machine's param `name` before a run (one check per name)."""
        if name in self.param_checks:
            raise ValueError(f"param '{name}' has a check already")
        self.param_checks[name] = check

    def add(self, *primitives: Primitive) -> None:
        for prim in primitives:
            if prim.spec.name in self._by_name:
                raise ValueError(f"primitive '{prim.spec.name}' is registered twice")
            self._by_name[prim.spec.name] = prim

    def get(self, name: str) -> Primitive | None:
        return self._by_name.get(name)

    def __contains__(self, name: object) -> bool:
        return name in self._by_name

    def __iter__(self) -> Iterator[Primitive]:
        return iter(self._by_name.values())

    def names(self) -> list[str]:
        return sorted(self._by_name)

    def for_world(self, world: str) -> Registry:
        """The primitives a run in `world` may call; the others are remembered in `elsewhere`."""
        kept = Registry(p for p in self if p.spec.world in (None, world))
        kept.elsewhere = {p.spec.name: str(p.spec.world) for p in self if p.spec.world not in (None, world)}
        kept.machine_folders = list(self.machine_folders)
        kept.clashes = dict(self.clashes)
        kept.param_checks = dict(self.param_checks)
        return kept

    @classmethod
    def discover(cls) -> Registry:
        """The primitives of every plug-in; a broken plug-in or a name taken twice is named and left out."""
        registry = cls()
        owners: dict[str, str] = {}
        for ep, register in plugins.load_each(GROUP, _register_problem):
            staging = cls()
            ok, _ = plugins.run_hook(ep, register, staging)
            if not ok:
                continue
            taken = [p.spec.name for p in staging if p.spec.name in registry]
            taken += [f"a check of param '{n}'" for n in staging.param_checks if n in registry.param_checks]
            for prim in staging:
                if prim.spec.name in registry:
                    registry.clashes[prim.spec.name] = (owners[prim.spec.name], ep.name)
            if taken:
                owner = owners[taken[0]]
                plugins.warn(
                    ep,
                    f"registers '{taken[0]}', which plug-in '{owner}' registered first",
                    "rename the primitive in one of them, or uninstall one",
                )
                continue
            registry.add(*staging)
            registry.param_checks.update(staging.param_checks)
            owners.update((p.spec.name, ep.name) for p in staging)
            owners.update((f"a check of param '{n}'", ep.name) for n in staging.param_checks)
        for ep, folder_of in plugins.load_each(MACHINES_GROUP, _callable_problem):
            ok, folder = plugins.run_hook(ep, folder_of)
            if ok:
                registry.machine_folders.append(Path(str(folder)))
        return registry


def _register_problem(ep: object, obj: object) -> str | None:
    if isinstance(obj, Primitive):
        return (
            f"names the primitive '{obj.spec.name}', not a register function: point it at a function "
            "`register(registry)` that calls `registry.add(...)`"
        )
    if not callable(obj):
        return f"names {type(obj).__name__} {obj!r}, not a register function `register(registry)`"
    return None


def _callable_problem(ep: Any, obj: Any) -> str | None:
    return None if callable(obj) else f"is {type(obj).__name__}, not a function returning a folder"
