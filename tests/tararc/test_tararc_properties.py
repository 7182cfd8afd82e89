"""Properties of grouping and allocation on random teams: a partition, the right sizes, one answer."""

import random
from dataclasses import dataclass

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm_behaviours.tararc.allocation import Task
from hfsm_behaviours.tararc.grouping import Group, Robot, form_groups, pair
from hfsm_behaviours.tararc.history import History, Record, record_run
from hfsm_behaviours.tararc.team import allocate


@dataclass(frozen=True)
class Team:
    robots: list[Robot]
    n_groups: int
    rel: dict[tuple[str, str], float]
    beliefs: dict[str, float]


@st.composite
def teams(draw: st.DrawFn) -> Team:
    n = draw(st.integers(1, 14))
    ids = [f"r{i}" for i in range(n)]
    coord = st.integers(-20, 20).map(float)  # whole metres: exact distance ties happen
    robots = [Robot(i, draw(coord), draw(coord)) for i in ids]
    level = st.sampled_from([0.0, 0.25, 0.5, 1.0])  # few levels: ties happen
    rel = {pair(a, b): draw(level) for k, a in enumerate(ids) for b in ids[k + 1:]}
    beliefs = {i: draw(level) for i in ids}
    return Team(robots, draw(st.integers(1, n)), rel, beliefs)


def groups_of(team: Team, robots: list[Robot], rel: dict[tuple[str, str], float]) -> list[Group]:
    return form_groups(robots, team.n_groups, rel, lambda r, o: team.beliefs[r] / (0.2 * o + 1))


@given(teams())
def test_every_robot_in_exactly_one_group_of_n_or_n_plus_one(team: Team) -> None:
    groups = groups_of(team, team.robots, team.rel)
    members = [m for g in groups for m in g.members]
    assert sorted(members) == sorted(r.id for r in team.robots)
    n, x = divmod(len(team.robots), team.n_groups)
    sizes = [len(g.members) for g in groups]
    assert len(groups) == team.n_groups
    assert sorted(sizes) == [n] * (team.n_groups - x) + [n + 1] * x
    assert all(g.agent in g.members for g in groups)


@given(teams(), st.randoms(use_true_random=False))
def test_same_answer_whatever_the_order_of_robots(team: Team, rnd: random.Random) -> None:
    first = groups_of(team, team.robots, team.rel)
    assert groups_of(team, team.robots, team.rel) == first
    robots = list(team.robots)
    rnd.shuffle(robots)
    items = list(team.rel.items())
    rnd.shuffle(items)
    assert groups_of(team, robots, dict(items)) == first


@given(teams(), st.randoms(use_true_random=False))
@settings(max_examples=50)
def test_allocation_is_a_matching_and_order_free(team: Team, rnd: random.Random) -> None:
    tasks = [Task(f"t{i}", float(i), 0.0, 0.1 + 0.8 * i / 14, 14 - i) for i in range(team.n_groups)]
    history = History(pairs={k: Record(int(4 * v), 1) for k, v in team.rel.items()})
    energy = {r.id: team.beliefs[r.id] for r in team.robots}
    out = allocate(team.robots, tasks, history, energy)
    assert sorted(t for t, _ in out.tasks) == sorted(t.id for t in tasks)
    assert sorted(g for _, g in out.tasks) == list(range(team.n_groups))
    robots, shuffled = list(team.robots), list(tasks)
    rnd.shuffle(robots)
    rnd.shuffle(shuffled)
    assert allocate(robots, shuffled, history, energy) == out


def test_six_robots_three_tasks_from_history() -> None:
    # history: (a, b) and (c, d) always succeeded together, (e, f) failed once: R(a,b) = R(c,d) = 1
    h = record_run(History(), [("a", "b"), ("c", "d"), ("e", "f")], [True, True, False])
    robots = [Robot("a", 0, 0), Robot("b", 0, 1), Robot("c", 10, 0), Robot("d", 10, 1),
              Robot("e", 5, 5), Robot("f", 5, 6)]
    tasks = [Task("hard", 9, 0, 0.9, 1), Task("easy", 1, 0, 0.1, 2), Task("mid", 5, 9, 0.5, 3)]
    out = allocate(robots, tasks, h, {r.id: 1.0 for r in robots})
    # groups: a seeds (row sum 1, tie with b, c, d: id) with b; c with d; e with f (R = 0)
    assert [g.members for g in out.groups] == [("a", "b"), ("c", "d"), ("e", "f")]
    # F at j_ord 0 with P^beta = 1 (a succeeded), d_t = mean 0.5, S = 1:
    # (0.2 + 0.2 + 0.1 + 0.2) / 1 = 0.7; at j_ord 1: 0.7 / 1.2. e and f failed: P^beta = 0.
    assert out.beliefs["a"] == pytest.approx(0.7)
    assert out.beliefs["b"] == pytest.approx(0.7 / 1.2)
    assert out.beliefs["e"] == pytest.approx(0.5)
    assert [g.agent for g in out.groups] == ["a", "c", "e"]
    # "hard" first: c is at distance 1, a at 9: c's group wins; "easy" (at 1 from a) goes to a;
    # "mid" is left for e's group.
    assert out.tasks == (("hard", 1), ("easy", 0), ("mid", 2))

