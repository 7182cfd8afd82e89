"""Plug-ins as users get them wrong, for tests/hfsm/test_plugins.py (entry points point here)."""

from __future__ import annotations

from hfsm.primitive import Context, primitive
from hfsm.registry import Registry


@primitive(outcomes=["done"])
def nod(ctx: Context) -> str:
    return "done"


@primitive(outcomes=["done"])
def wave(ctx: Context) -> str:
    return "done"


def register_nod(registry: Registry) -> None:
    registry.add(nod)


def register_nod_and_wave(registry: Registry) -> None:
    registry.add(nod, wave)


def register_wave(registry: Registry) -> None:
    registry.add(wave)


def register_broken(registry: Registry) -> None:
    raise RuntimeError("no robot here")


NOT_CALLABLE = 42
