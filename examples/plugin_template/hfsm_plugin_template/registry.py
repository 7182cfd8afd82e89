"""The plug-in's entry points (see pyproject.toml)."""

from __future__ import annotations

from importlib.resources import files
from importlib.resources.abc import Traversable

from hfsm.registry import Registry
from hfsm_plugin_template.primitives import count_down


def register(registry: Registry) -> None:
    """`hfsm.primitives`: add this package's primitives."""
    registry.add(count_down)


def machines() -> Traversable:
    """`hfsm.machines`: the folder of this package's machine files."""
    return files("hfsm_plugin_template") / "machines"
