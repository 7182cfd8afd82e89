"""`hfsm-run --list`: every behaviour a run can call, as Markdown (docs/BEHAVIOURS.md is its output).

Built-ins, the registered primitives (from their declarations: no simulator is imported) and the
machines along the search path (`--lib` folders, then the plug-ins' machines and the project's).
"""

from __future__ import annotations

import fnmatch
import json
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from hfsm.builtins import BUILTINS
from hfsm.checks.context import machine_spec
from hfsm.errors import UserError
from hfsm.library import PROJECT_MACHINES, SUFFIXES, load_machine_file
from hfsm.primitive import Primitive
from hfsm.registry import Registry
from hfsm.spec import BehaviourSpec, ParamSpec

HEADER = """# Behaviours

Every behaviour a machine can call with `do:`: the built-ins, the primitives of the installed
plug-ins and the machines found by name. Failures are the outcomes that count as failing; outputs
are what `save:` may take.
"""


def machine_folders(libs: Iterable[Path]) -> list[Path]:
    folders = [*(p.resolve() for p in libs), PROJECT_MACHINES]
    return [f for i, f in enumerate(folders) if f not in folders[:i] and f.is_dir()]


def machine_specs(folders: Iterable[Path]) -> list[tuple[BehaviourSpec, str]]:
    """Each machine file's spec and where it is, the first of a name along the folders winning."""
    found: dict[str, tuple[BehaviourSpec, str]] = {}
    for folder in folders:
        for path in sorted(p for p in folder.iterdir() if p.suffix in SUFFIXES):
            if path.stem in found:
                continue
            try:
                found[path.stem] = (machine_spec(load_machine_file(path)), _shown(path))
            except UserError:
                continue  # a broken file is `--check`'s to report
    return [found[name] for name in sorted(found)]


def _shown(path: Path) -> str:
    try:
        return str(path.relative_to(PROJECT_MACHINES.parent))
    except ValueError:
        return str(path)


def render(registry: Registry, libs: Iterable[Path], pattern: str = "") -> str:
    """Every behaviour a run can call, or those whose name matches `pattern` (a part of the name, or
    a shell pattern such as `tararc_*`) or whose world it names (`sim`)."""
    def shown(spec: BehaviourSpec) -> bool:
        return matches(spec, pattern)

    machines = [(spec, where) for spec, where in machine_specs(machine_folders(libs)) if shown(spec)]
    out = [HEADER if not pattern else f"# Behaviours matching '{pattern}'\n"]
    sections = [
        ("Built-ins", [_entry(spec, "built-in") for spec in BUILTINS.values() if shown(spec)]),
        ("Primitives", [_primitive(p) for p in sorted(registry, key=lambda p: p.spec.name) if shown(p.spec)]),
        ("Machines", [_entry(spec, f"machine `{where}`") for spec, where in machines]),
    ]
    for title, entries in sections:
        if entries or not pattern:
            out += [f"## {title}\n", *entries]
    if pattern and len(out) == 1:
        out.append(f"No behaviour's name or world matches '{pattern}'.\n")
    return "\n".join(out)


def matches(spec: BehaviourSpec, pattern: str) -> bool:
    if not pattern:
        return True
    low = pattern.lower()
    return low in spec.name or fnmatch.fnmatchcase(spec.name, low) or low == (spec.world or "")


def _primitive(prim: Primitive) -> str:
    world = f", world `{prim.spec.world}`" if prim.spec.world else ""
    return _entry(prim.spec, f"primitive `{prim.where}`{world}")


def _entry(spec: BehaviourSpec, what: str) -> str:
    lines = [f"### `{spec.name}`", "", f"{_first_line(spec.doc)} ({what})", ""]
    if spec.open_params:
        lines.append("- params: any of the caller's vars")
    elif spec.params:
        lines.append("- params: " + ", ".join(_param(p) for p in spec.params.values()))
    lines.append("- outcomes: " + ", ".join(f"`{o}`" for o in spec.outcomes))
    if spec.failures:
        lines.append("- failures: " + ", ".join(f"`{f}`" for f in sorted(spec.failures)))
    if spec.outputs is None:
        lines.append("- outputs: open (any name)")
    elif spec.outputs:
        lines.append("- outputs: " + ", ".join(f"`{o}`" for o in sorted(spec.outputs)))
    return "\n".join(lines) + "\n"


def _param(p: ParamSpec) -> str:
    default = "" if p.required else f" = {_literal(p.default)}"
    doc = f" ({p.doc})" if p.doc else ""
    return f"`{p.name}: {p.type}{default}`{doc}"


def _literal(value: Any) -> str:
    return json.dumps(value, ensure_ascii=False, default=str)


def _first_line(doc: str) -> str:
    line = doc.strip().split("\n\n")[0].replace("\n", " ")
    return line or "(no doc)"
