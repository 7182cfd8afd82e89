"""Primitives of the approach: find the table, elect a leader, clear the way, reach the long sides."""

from __future__ import annotations

from hfsm.primitive import Primitive
from hfsm_behaviours.approach.around import go_to_opposite_side_of_table
from hfsm_behaviours.approach.assist import clear_way, look_for_leader, sense_own_colour
from hfsm_behaviours.approach.corner import go_to_table
from hfsm_behaviours.approach.search import centre_table, scan_for_table, spin_on_the_spot, walk_randomly
from hfsm_behaviours.approach.side import go_to_the_lifting_point, position_to_centre_of_table_side

PRIMITIVES: tuple[Primitive, ...] = (
    scan_for_table,
    spin_on_the_spot,
    walk_randomly,
    centre_table,
    go_to_table,
    position_to_centre_of_table_side,
    go_to_the_lifting_point,
    sense_own_colour,
    look_for_leader,
    clear_way,
    go_to_opposite_side_of_table,
)
