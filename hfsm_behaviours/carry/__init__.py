"""Primitives of the carry (the paper's Move table, Figure 3): align, lift together, step, land.

`machines/move_table.yaml` cycles through them; `machines/synchronised_lift_table.yaml` is the
lift handshake (Behaviour 1) around `lift_table`; `machines/align_to_middle_of_table.yaml` is the
loop of Behaviour 2 over `look_left_and_right`, `align_body_parallel` and `walk_sideways`.
"""

from __future__ import annotations

from hfsm.primitive import Primitive
from hfsm_behaviours.carry.centre import align_body_parallel, look_left_and_right, walk_sideways
from hfsm_behaviours.carry.lifting import land_table, lift_table
from hfsm_behaviours.carry.square import recentre_to_middle_of_table
from hfsm_behaviours.carry.stepping import small_step_sideways
from hfsm_behaviours.carry.wall import choose_carry_direction, table_at_wall

PRIMITIVES: tuple[Primitive, ...] = (
    recentre_to_middle_of_table,
    look_left_and_right,
    align_body_parallel,
    walk_sideways,
    lift_table,
    small_step_sideways,
    land_table,
    choose_carry_direction,
    table_at_wall,
)
