"""Pairs whose ways meet take turns (hfsm_behaviours/room/claims.turns): one order for the room."""

from __future__ import annotations

from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.room.claims import claim_walls, side_by_side, turns, way


def waits(tables: list[dict[str, Any]], width: float = 8.0, depth: float = 6.0) -> dict[str, list[str]]:
    return turns(claim_walls(tables, width, depth), tables)


def test_tables_far_apart_take_no_turns() -> None:
    tables = [{"id": "a", "x": -2.5, "y": -1.5, "yaw": 0}, {"id": "b", "x": 2.5, "y": 1.5, "yaw": 0}]
    assert waits(tables) == {"a": [], "b": []}


def test_tables_side_by_side_0_8_m_apart_take_turns() -> None:
    """Their long sides 0.8 m apart: the robots standing between them would stand back to back."""
    tables = [{"id": "a", "x": 0.0, "y": -0.65, "yaw": 0}, {"id": "b", "x": 0.0, "y": 0.65, "yaw": 0}]
    got = waits(tables)
    assert sorted([got["a"], got["b"]]) == [[], ["a"]]  # one waits for the other, by id at equal travel


def test_a_table_standing_in_anothers_way_goes_first() -> None:
    """b is carried east (given), over where a stands: a goes first though b's travel is shorter."""
    a = {"id": "a", "x": 2.5, "y": 0.0, "yaw": 90, "length": 0.8}
    b = {"id": "b", "x": 1.0, "y": 0.0, "yaw": 0, "length": 1.4}
    ways = {"a": way(a, 1, 8.0, 6.0, 0.5), "b": way(b, 1, 8.0, 6.0, 0.5)}
    assert ways["b"].travel < ways["a"].travel
    assert turns(ways, [a, b]) == {"a": [], "b": ["a"]}


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-3.0, 3.0), st.floats(-2.0, 2.0), st.sampled_from([0, 30, 45, 90, 135])),
                min_size=1, max_size=5))
def test_no_two_pairs_ever_wait_for_each_other(spots: list[tuple[float, float, int]]) -> None:
    tables = [{"id": f"t{i}", "x": x, "y": y, "yaw": yaw} for i, (x, y, yaw) in enumerate(spots)]
    got = waits(tables)
    order: list[str] = []
    left = dict(got)
    while left:  # a table goes once every table it waits for has gone: all go, so no cycle
        ready = [t for t, after in left.items() if all(a in order for a in after)]
        assert ready, left
        order += sorted(ready)
        for t in ready:
            del left[t]


def test_a_way_meeting_its_wall_grazing_is_carried_the_other_way() -> None:
    """Development room walls-902: table2 at 21 degrees, 1.55 m from the north wall, was carried to it
    (its nearer wall along its axis, 69 degrees from square on) and slid along it into the corner; the
    other way meets the west wall 21 degrees from square on, and is taken though it is longer."""
    tables = [{"id": "table1", "x": 5.44, "y": -2.3, "yaw": 82.0, "length": 0.86, "width": 0.47},
              {"id": "table2", "x": -0.41, "y": 1.75, "yaw": 21.0, "length": 1.0, "width": 0.57}]
    north = way(tables[1], 1, 13.8, 6.6, 0.5)
    west = way(tables[1], -1, 13.8, 6.6, 0.5)
    assert north.grazing and not west.grazing and north.travel < west.travel
    claims = claim_walls(tables, 13.8, 6.6)
    assert claims["table2"].sign == -1 and claims["table2"].toward[0] == -6.9
    assert claims["table1"].sign == -1  # 8 degrees from square on: kept the shorter way


def test_tables_side_by_side_are_carried_to_opposite_walls() -> None:
    """Two tables 0.8 m apart carried to one wall would end there side by side, 0.3 m apart, their
    pairs back to back, and the second leader looking along its edge saw the first table's end as
    its own (tests/behaviours/test_room_turns_sim.py): at equal travel they go to opposite walls."""
    tables = [{"id": "a", "x": 0.0, "y": -0.65, "yaw": 0}, {"id": "b", "x": 0.0, "y": 0.65, "yaw": 0}]
    ways = claim_walls(tables, 7.0, 5.0)
    assert {ways["a"].sign, ways["b"].sign} == {1, -1}
    assert side_by_side(list(ways.values()), tables) == 0
    assert side_by_side([way(t, 1, 7.0, 5.0, 0.5) for t in tables], tables) == 1


def test_tables_far_apart_on_one_wall_are_not_side_by_side() -> None:
    tables = [{"id": "a", "x": 0.0, "y": -1.5, "yaw": 0}, {"id": "b", "x": 0.0, "y": 1.5, "yaw": 0}]
    assert side_by_side([way(t, 1, 7.0, 5.0, 0.5) for t in tables], tables) == 0


def test_tables_whose_places_crowd_each_other_take_turns() -> None:
    """Held-out room walls-39001: two tables 2 m apart (1.4 m between their sides), both carried to the
    north wall 0.85 m away; each pair's place between them lay within 0.5 m of the other table, and
    table2's assistant walking round its table met table1's assistant standing at its place (4
    contacts). A place within NEAR m of the other's top: the pairs take turns."""
    tables = [{"id": "table1", "x": 0.36, "y": 4.1, "yaw": 82.0, "length": 0.68, "width": 0.65},
              {"id": "table2", "x": 2.36, "y": 4.11, "yaw": 74.0, "length": 0.62, "width": 0.54}]
    got = waits(tables, 7.5, 9.9)
    assert sorted([got["table1"], got["table2"]]) == [[], ["table1"]] or sorted(
        [got["table1"], got["table2"]]) == [[], ["table2"]]
    apart = [{**tables[0], "x": -1.5}, tables[1]]  # 3.9 m apart: no place near the other
    assert waits(apart, 7.5, 9.9) == {"table1": [], "table2": []}
