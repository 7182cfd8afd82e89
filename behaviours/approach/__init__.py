"""Primitives of the approach: find the table, elect a leader, clear the way, reach the long sides."""

from __future__ import annotations

from hfsm.primitive import Primitive

PRIMITIVES: tuple[Primitive, ...] = ()
