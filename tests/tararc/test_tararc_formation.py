"""Where robots stand: forming up round their agent by where they are, and enclosing a task."""

from __future__ import annotations

import itertools
import math

from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.tararc.formation import assign, enclose, form_places, radius

BOX = ((-20.0, -20.0), (20.0, 20.0))


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 5).flatmap(lambda n: st.tuples(
    st.just(n), st.integers(n, 6).flatmap(lambda m: st.lists(
        st.lists(st.integers(0, 20), min_size=m, max_size=m), min_size=n, max_size=n)))))
def test_assign_is_the_least_total_cost(case: tuple[int, list[list[int]]]) -> None:
    n, costs = case
    got = assign(costs)
    assert len(set(got)) == n
    best = min(sum(costs[i][j] for i, j in enumerate(p)) for p in itertools.permutations(range(len(costs[0])), n))
    assert sum(costs[i][j] for i, j in enumerate(got)) == best


def test_a_member_beside_its_agent_is_in_place_and_one_across_comes_to_its_side() -> None:
    starts = {"a": (0.0, 0.0), "b": (1.0, 0.0), "c": (-3.0, 0.2)}
    places = form_places([("a", ["a", "b", "c"])], starts, BOX, 1.0, 0.8)
    assert places["a"] == (0.0, 0.0) and places["b"] == (1.0, 0.0)
    assert math.dist(places["c"], (-1.0, 0.0)) < 0.3  # the side of a facing c, 1 m off


def crowd(rows: int, cols: int, gap: float) -> dict[str, tuple[float, float]]:
    return {f"r{i * cols + j}": (j * gap, i * gap) for i in range(rows) for j in range(cols)}


def test_in_a_crowd_no_two_places_are_closer_than_the_gap() -> None:
    starts = crowd(6, 5, 0.8)
    ids = sorted(starts, key=lambda r: int(r[1:]))
    groups = [(ids[k], ids[k::10]) for k in range(10)]  # scattered groups of 3, as ids make them
    box = ((-1.0, -1.0), (6.0, 6.0))
    places = form_places(groups, starts, box, 1.0, 0.8)
    assert set(places) == set(starts)
    for (a, p), (b, q) in itertools.combinations(places.items(), 2):
        assert math.dist(p, q) >= 0.8 - 1e-9, (a, b)
    for agent, members in groups:
        assert math.dist(places[agent], starts[agent]) < 1e-6
        for m in members:
            assert box[0][0] <= places[m][0] <= box[1][0] and box[0][1] <= places[m][1] <= box[1][1]


def test_places_do_not_depend_on_the_order_groups_are_given_in() -> None:
    starts = crowd(3, 4, 0.8)
    groups = [("r0", ["r0", "r5", "r10"]), ("r3", ["r3", "r1", "r8"]), ("r6", ["r6", "r2", "r4", "r7", "r9", "r11"])]
    one = form_places(groups, starts, BOX, 1.0, 0.8)
    other = form_places([(a, list(reversed(ms))) for a, ms in reversed(groups)], starts, BOX, 1.0, 0.8)
    assert one == other


def test_the_ring_grows_with_the_group() -> None:
    assert radius(3, 1.0, 0.8) == 1.0
    assert radius(12, 1.0, 0.8) == 12 * 0.8 / (2 * math.pi)


def test_members_enclose_the_task_on_the_side_they_come_from() -> None:
    where = {"b": (-2.0, 1.0), "c": (-2.0, -1.0)}
    places = enclose((5.0, 0.0), ["b", "c"], where, 1.0, 0.8, came_from=(0.0, 0.0))
    assert places["b"][1] > 0 > places["c"][1]  # no crossing
    assert all(p[0] < 5.0 + 1e-9 and abs(math.dist(p, (5.0, 0.0)) - 1.0) < 1e-9 for p in places.values())
