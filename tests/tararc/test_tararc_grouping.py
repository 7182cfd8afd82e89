"""TARARC steps 2-5: grouping, election, leftovers and competition on small teams."""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.tararc.allocation import Task, compete
from hfsm_behaviours.tararc.grouping import (
    Group,
    Robot,
    elect,
    form_groups,
    greedy_groups,
    group_size,
    pair,
    row_sum,
)


def rel(**pairs: float) -> dict[tuple[str, str], float]:
    """rel(r0_r1=0.9) is {('r0', 'r1'): 0.9}."""
    return {pair(*k.split("_")): v for k, v in pairs.items()}


def line(*xs: float) -> list[Robot]:
    return [Robot(f"r{i}", x, 0.0) for i, x in enumerate(xs)]


def test_group_sizes_are_n_or_n_plus_one() -> None:
    assert group_size(50, 20) == (2, 10)  # the paper's example: 10 groups of 3, 10 of 2
    assert group_size(6, 2) == (3, 0)
    with pytest.raises(ValueError, match="merge tasks"):
        group_size(2, 3)


def test_six_robots_two_groups_follow_the_row_sums() -> None:
    r = rel(r0_r1=0.9, r0_r2=0.8, r3_r4=0.7, r4_r5=0.6, r3_r5=0.5, r2_r3=0.1)
    # row sums: r0 = 0.9+0.8 = 1.7, r1 = 0.9, r2 = 0.8+0.1 = 0.9, r3 = 0.7+0.5+0.1 = 1.3,
    # r4 = 0.7+0.6 = 1.3, r5 = 0.6+0.5 = 1.1. r0 seeds and takes r1 (0.9), r2 (0.8).
    # Left r3, r4, r5: r3 = 0.7+0.5 = 1.2, r4 = 1.3, r5 = 1.1: r4 seeds, takes r3 (0.7), r5 (0.6).
    groups, left = greedy_groups([f"r{i}" for i in range(6)], 2, r)
    assert groups == [("r0", "r1", "r2"), ("r4", "r3", "r5")]
    assert left == []


def test_without_history_ties_go_by_id() -> None:
    groups, left = greedy_groups(["r3", "r1", "r2", "r0"], 2, {})
    assert groups == [("r0", "r1"), ("r2", "r3")]
    assert left == []


def test_leftovers_go_to_the_last_groups_nearest_agent_first() -> None:
    # 6 robots, 4 groups: n = 1, x = 2. No history: seeds r0..r3 by id, r4 and r5 left over.
    # The last 2 groups (agents r2 at x=0 and r3 at x=10) each take the leftover nearest their
    # agent in turn: r2 takes r5 (|1-0| = 1 < |9-0| = 9), then r3 takes r4.
    robots = [Robot("r0", 5, 5), Robot("r1", 5, -5), Robot("r2", 0, 0), Robot("r3", 10, 0),
              Robot("r4", 9, 0), Robot("r5", 1, 0)]
    groups = form_groups(robots, 4, {}, lambda r, o: 0.5)
    assert groups == [Group("r0", ("r0",)), Group("r1", ("r1",)), Group("r2", ("r2", "r5")),
                      Group("r3", ("r3", "r4"))]


def test_election_takes_the_highest_belief_at_its_place() -> None:
    base = {"r0": 0.5, "r1": 0.66, "r2": 0.66}
    # F = base / (0.2*j_ord + 1): r0 0.5/1 = 0.5, r1 0.66/1.2 = 0.55, r2 0.66/1.4 = 0.471
    assert elect(("r0", "r1", "r2"), lambda r, o: base[r] / (0.2 * o + 1)) == "r1"
    assert elect(("r2", "r1"), lambda r, o: 0.3) == "r1"  # a tie goes to the smaller id


def test_three_robots_one_group_elects_by_belief() -> None:
    r = rel(r0_r1=0.5, r1_r2=0.9)
    # row sums r0 0.5, r1 1.4, r2 0.9: r1 seeds, then r2 (0.9), r0 (0.5): members (r1, r2, r0)
    beliefs = {"r0": 0.9, "r1": 0.2, "r2": 0.4}
    groups = form_groups(line(0, 1, 2), 1, r, lambda rb, o: beliefs[rb])
    assert groups == [Group("r0", ("r1", "r2", "r0"))]


def test_four_robots_compete_in_priority_order() -> None:
    # groups (r0, r1) and (r2, r3) by history; agents r0 at x=0 and r2 at x=4 (equal F = 0.6)
    r = rel(r0_r1=1.0, r2_r3=1.0)
    robots = [Robot("r0", 0, 0), Robot("r1", 0, 1), Robot("r2", 4, 0), Robot("r3", 4, 1)]
    groups = form_groups(robots, 2, r, lambda rb, o: 0.6 / (0.2 * o + 1))
    assert [g.agent for g in groups] == ["r0", "r2"]
    near, far = Task("t1", 1, 0, 0.5, 1), Task("t2", 4, 0, 0.5, 2)
    agents = [robots[0], robots[2]]
    # t1 first: B(r0) = 0.6 / (0.05*sqrt(1) + 0.05*0.5) = 0.6/0.075 = 8,
    #           B(r2) = 0.6 / (0.05*sqrt(3) + 0.025) = 5.376: r0 wins t1, r2 gets t2.
    assert compete([far, near], agents, lambda a, d: 0.6) == [("t1", "r0"), ("t2", "r2")]
    # t2 first: B(r0) = 0.6 / (0.05*2 + 0.025) = 4.8, B(r2) = 0.6 / 0.025 = 24: r2 wins t2.
    swapped = [Task("t1", 1, 0, 0.5, 2), Task("t2", 4, 0, 0.5, 1)]
    assert compete(swapped, agents, lambda a, d: 0.6) == [("t2", "r2"), ("t1", "r0")]


def test_competition_ties_go_by_agent_id_and_extra_tasks_wait() -> None:
    agents = [Robot("b", 2, 0), Robot("a", 0, 0)]
    tasks = [Task("t1", 1, 0, 0.5, 1), Task("t2", 0, 0, 0.5, 2), Task("t3", 9, 9, 0.5, 3)]
    # t1 is at distance 1 from both: a tie, a wins; t2 goes to b, the only one left; t3 waits
    assert compete(tasks, agents, lambda a, d: 0.6) == [("t1", "a"), ("t2", "b")]


def test_competition_uses_belief_at_the_task_difficulty() -> None:
    agents = [Robot("a", 0, 0), Robot("b", 0, 0)]
    hard = Task("t", 1, 0, 0.9, 1)
    # a is better at hard tasks: F(a) = 0.1 + d, F(b) = 0.5: at d = 0.9, 1.0 > 0.5
    assert compete([hard], agents, lambda ag, d: 0.1 + d if ag == "a" else 0.5) == [("t", "a")]


def _greedy_by_row_sums(ids: list[str], n_groups: int, rel: dict[tuple[str, str], float]) -> tuple[list[tuple[str, ...]], list[str]]:
    """Step 2 as written first: every seed key a row sum over the whole pool (the reference)."""
    pool = sorted(set(ids))
    n, _ = group_size(len(pool), n_groups)
    groups: list[tuple[str, ...]] = []
    for _ in range(n_groups):
        seed = min(pool, key=lambda r: (-row_sum(r, pool, rel), 0.0, r))
        rest = [r for r in pool if r != seed]
        partners = sorted(rest, key=lambda r: (-rel.get(pair(seed, r), 0.0), (), r))[: n - 1]
        groups.append((seed, *partners))
        pool = [r for r in pool if r not in {seed, *partners}]
    return groups, pool


@settings(max_examples=200, deadline=None)
@given(st.integers(2, 12).flatmap(lambda n: st.tuples(
    st.just(n), st.integers(1, n),
    st.dictionaries(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)),
                    st.sampled_from([0.0, -0.0, 1e-300, 0.1, 0.2, 0.3, 1e16, -1.0, 2.5]), max_size=40))))
def test_greedy_groups_are_those_of_the_row_sums_over_the_whole_pool(
    case: tuple[int, int, dict[tuple[int, int], float]],
) -> None:
    n, n_groups, raw = case
    rel = {(f"r{a}", f"r{b}"): v for (a, b), v in raw.items()}  # also keys `pair` never makes
    ids = [f"r{i}" for i in range(n)]
    assert greedy_groups(ids, n_groups, rel) == _greedy_by_row_sums(ids, n_groups, rel)
