"""Primitives of the carry (the paper's Move table, Figure 3): align, lift together, step, land."""

from __future__ import annotations

from hfsm.primitive import Primitive

PRIMITIVES: tuple[Primitive, ...] = ()
