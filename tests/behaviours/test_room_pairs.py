"""Issue 10: two pairs carry two tables in one room at once, each robot told its table, partner,
channel and role (tests/room_run.py); a robot that fails mid-carry leaves its partner to land the
table and end `partner_lost` in bounded time, while the other pair carries on."""

from __future__ import annotations

import math

import pytest
from room_run import run_pairs, to_room

from hfsm_sim import load_scenario


@pytest.mark.slow
def test_two_pairs_carry_two_tables_to_the_walls() -> None:
    room = run_pairs("room_2_tables", 0)
    assert room.outcomes == dict.fromkeys(["r1", "r2", "r3", "r4"], "at_wall")
    assert room.roles == {"r1": "leader", "r2": "assistant", "r3": "leader", "r4": "assistant"}
    assert all(d <= 0.15 for d in room.score["table_wall_distances"])
    assert not room.score["dropped"] and room.score["robot_collisions"] == 0
    scenario = load_scenario("room_2_tables")
    for robot, table in {"r1": "table1", "r2": "table1", "r3": "table2", "r4": "table2"}.items():
        seen = to_room(scenario, robot, room.outputs[robot]["table_at"])
        assert math.dist(seen, room.ends[table]) < 0.5, f"{robot} says where {table} was left"


@pytest.mark.slow
def test_a_robot_failing_mid_carry_leaves_its_partner_to_land_the_table() -> None:
    """r2 (table1's assistant) fails at 80 s, in the carry: the table falls (the sim drops what a
    failed robot holds); r1 hears no heartbeat for 20 s, lands its side and ends partner_lost;
    the other pair carries table2 to the wall."""
    room = run_pairs("room_2_tables", 0, failures={"r2": 80.0})
    assert room.outcomes["r2"] == "None"
    assert room.outcomes["r1"] == "partner_lost"
    assert not room.holding["r1"], "the survivor put its side down"
    assert 100.0 <= room.times["r1"] <= 120.0, "bounded: the silence (20 s) and a landing"
    assert room.outcomes["r3"] == room.outcomes["r4"] == "at_wall"
    assert room.score["table_wall_distances"][1] <= 0.15
    assert room.score["robot_collisions"] == 0
