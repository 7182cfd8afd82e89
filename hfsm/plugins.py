"""Loading plug-ins (entry points) so that a broken one is named, with its fix, and left out:
commands that do not need it keep working."""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterator
from importlib.metadata import EntryPoint, entry_points
from typing import Any

log = logging.getLogger("hfsm.plugins")

RENAMED = {"behaviours": ("behaviours", "hfsm_behaviours"), "sim": ("sim", "hfsm_sim")}
"""Packages of hfsm that were renamed so that the wheel installs only names of its own."""


def describe(ep: EntryPoint) -> str:
    return f"plug-in '{ep.name}' ({ep.value}, entry-point group {ep.group})"


def warn(ep: EntryPoint, problem: str, fix: str) -> None:
    log.warning("warning: %s %s; %s. It is left out.", describe(ep), problem, fix)


def load_each(group: str, check: Callable[[EntryPoint, Any], str | None]) -> Iterator[tuple[EntryPoint, Any]]:
    """Each entry point of `group`, sorted by name, loaded; `check` returns a problem or None."""
    for ep in sorted(entry_points(group=group), key=lambda e: e.name):
        try:
            obj = ep.load()
        except ImportError as exc:
            renamed = RENAMED.get((exc.name or "").partition(".")[0])
            if renamed is None:
                warn(ep, f"cannot be imported ({type(exc).__name__}: {exc})", "fix or uninstall that package")
            else:
                old, new = renamed
                where = "names" if ep.module.partition(".")[0] == old else "imports"
                warn(ep, f"{where} the module '{old}', which hfsm renamed '{new}'",
                     f"write '{new}' for '{old}' in that package (its entry points and imports)")
            continue
        except Exception as exc:  # a plug-in's import may fail in any way: name it, go on
            warn(ep, f"cannot be imported ({type(exc).__name__}: {exc})", "fix or uninstall that package")
            continue
        problem = check(ep, obj)
        if problem:
            warn(ep, problem, "point the entry point at the right object")
            continue
        yield ep, obj


def run_hook(ep: EntryPoint, hook: Callable[..., Any], *args: Any) -> tuple[bool, Any]:
    """Call a plug-in's function; on an exception, name the plug-in and report failure."""
    try:
        return True, hook(*args)
    except Exception as exc:  # the plug-in's own code: name it, go on without it
        warn(ep, f"failed ({type(exc).__name__}: {exc})", "fix or uninstall that package")
        return False, None
