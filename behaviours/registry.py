"""The `hfsm.primitives` entry point: every primitive of this package."""

from __future__ import annotations

from hfsm.registry import Registry


def register(registry: Registry) -> None:
    """Add this package's primitives to a registry."""
    from behaviours import approach, carry

    registry.add(*approach.PRIMITIVES, *carry.PRIMITIVES)
