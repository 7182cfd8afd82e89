"""Primitives of the carry (the paper's Move table, Figure 3): align, lift together, step, land.

`machines/move_table.yaml` cycles through them; `machines/synchronised_lift_table.yaml` is the
lift handshake (Behaviour 1) around `lift_table`.
"""

from __future__ import annotations

from behaviours.carry.centre import align_to_middle_of_table
from behaviours.carry.lifting import land_table, lift_table
from behaviours.carry.square import recentre_to_middle_of_table
from behaviours.carry.stepping import small_step_sideways
from behaviours.carry.wall import choose_carry_direction, table_at_wall
from hfsm.primitive import Primitive

PRIMITIVES: tuple[Primitive, ...] = (
    recentre_to_middle_of_table,
    align_to_middle_of_table,
    lift_table,
    small_step_sideways,
    land_table,
    choose_carry_direction,
    table_at_wall,
)
