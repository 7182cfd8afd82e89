"""TARARC step 7: the help strategies as pure decisions (7a hand-over, 7b lending members)."""

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.tararc.grouping import Group, Robot
from hfsm_behaviours.tararc.help import HandOver, Transfer, apply_transfers, hand_over, lend


def test_7a_a_tired_agent_hands_over_to_the_highest_belief() -> None:
    group = Group("r0", ("r0", "r1", "r2"))
    beliefs = {"r0": 0.9, "r1": 0.4, "r2": 0.5}
    # S = 0.1 < S_thres = 0.2: r2 (0.5 > 0.4) takes over, r0 leaves the group
    assert hand_over(group, 0.1, 0.2, beliefs) == HandOver("r0", "r2", Group("r2", ("r1", "r2")))


def test_7a_no_hand_over_with_enough_energy_or_nobody_left() -> None:
    assert hand_over(Group("r0", ("r0", "r1")), 0.2, 0.2, {"r1": 1.0}) is None  # S = S_thres is enough
    assert hand_over(Group("r0", ("r0",)), 0.0, 0.2, {}) is None


def test_7a_ties_go_by_id() -> None:
    handed = hand_over(Group("r9", ("r9", "r5", "r3")), 0.0, 0.5, {"r5": 0.4, "r3": 0.4})
    assert handed is not None and handed.new == "r3"


def robots(**where: float) -> dict[str, Robot]:
    return {k: Robot(k, x, 0.0) for k, x in where.items()}


def test_7b_nearest_group_gives_first_and_keeps_n_thres() -> None:
    # g0 lost its members: (r0,), n_thres = 3. Agents: r1 at 1 (nearest), r2 at 3.
    # g1 has 3 robots = n_thres: it cannot spare one. g2 has 4: gives the member nearest r0,
    # r7 and r8 both at 4 -> r7 by id. g2 is then at 3 and stops; g0 stays short (2 < 3).
    groups = [Group("r0", ("r0",)), Group("r1", ("r1", "r4", "r5")), Group("r2", ("r2", "r6", "r7", "r8"))]
    where = robots(r0=0, r1=1, r4=5, r5=2, r2=3, r6=6, r7=4, r8=4)
    assert lend(groups, 0, 3, where) == [Transfer("r7", 2, 0)]


def test_7b_groups_give_in_turn_nearest_first() -> None:
    # g0 = (r0,) needs 1 robot for n_thres = 2: the nearest group g1 (agent at 1) gives r5 (at 2).
    # For n_thres = 4 it needs 3: round 1, g1 gives r5, then g2 (agent at 3) gives r7 (at 4);
    # round 2, g1 (5 robots > 4) gives r4 (at 5, its nearest left); g0 has 4, done.
    groups = [Group("r0", ("r0",)), Group("r1", ("r1", "r4", "r5", "r9", "r10", "r11")),
              Group("r2", ("r2", "r6", "r7", "r8", "r12"))]
    where = robots(r0=0, r1=1, r4=5, r5=2, r9=7, r10=8, r11=9, r2=3, r6=6, r7=4, r8=4.5, r12=10)
    assert lend(groups, 0, 2, where) == [Transfer("r5", 1, 0)]
    moves = lend(groups, 0, 4, where)
    assert moves == [Transfer("r5", 1, 0), Transfer("r7", 2, 0), Transfer("r4", 1, 0)]
    after = apply_transfers(groups, moves)
    assert after[0] == Group("r0", ("r0", "r5", "r7", "r4"))
    assert after[1] == Group("r1", ("r1", "r9", "r10", "r11"))
    assert after[2] == Group("r2", ("r2", "r6", "r8", "r12"))


def test_7b_a_full_group_needs_nothing() -> None:
    groups = [Group("r0", ("r0", "r1")), Group("r2", ("r2", "r3", "r4"))]
    assert lend(groups, 0, 2, robots(r0=0, r1=0, r2=1, r3=1, r4=1)) == []
    with pytest.raises(ValueError):
        lend(groups, 0, 0, robots(r0=0, r1=0, r2=1, r3=1, r4=1))


@st.composite
def split_teams(draw: st.DrawFn) -> tuple[list[Group], dict[str, Robot], int]:
    sizes = draw(st.lists(st.integers(1, 6), min_size=2, max_size=6))
    groups, where, k = [], {}, 0
    for size in sizes:
        ids = [f"r{k + i}" for i in range(size)]
        k += size
        groups.append(Group(draw(st.sampled_from(ids)), tuple(ids)))
        for i in ids:
            where[i] = Robot(i, draw(st.integers(-9, 9)), draw(st.integers(-9, 9)))
    return groups, where, draw(st.integers(1, 6))


@given(split_teams(), st.data())
def test_7b_lending_keeps_a_partition_and_the_givers_whole(
    team: tuple[list[Group], dict[str, Robot], int], data: st.DataObject
) -> None:
    groups, where, n_thres = team
    needy = data.draw(st.integers(0, len(groups) - 1))
    moves = lend(groups, needy, n_thres, where)
    after = apply_transfers(groups, moves)
    assert sorted(m for g in after for m in g.members) == sorted(where)
    assert all(t.member != groups[t.giver].agent for t in moves)
    for i, (before, now) in enumerate(zip(groups, after, strict=True)):
        assert now.agent == before.agent
        if i != needy:
            assert len(now.members) >= min(len(before.members), n_thres)
    others_spare = sum(max(0, len(g.members) - n_thres) for i, g in enumerate(groups) if i != needy)
    short = max(0, n_thres - len(groups[needy].members))
    assert len(moves) == min(short, others_spare)
    assert lend(groups, needy, n_thres, where) == moves


@given(st.lists(st.integers(0, 3), min_size=1, max_size=6, unique=False), st.floats(0, 1), st.floats(0, 1))
def test_7a_the_new_agent_has_the_highest_belief(levels: list[int], energy: float, thres: float) -> None:
    ids = tuple(f"r{i}" for i in range(len(levels)))
    beliefs = {i: float(v) for i, v in zip(ids, levels, strict=True)}
    handed = hand_over(Group(ids[0], ids), energy, thres, beliefs)
    if energy >= thres or len(ids) == 1:
        assert handed is None
        return
    assert handed is not None and handed.old == ids[0] and ids[0] not in handed.group.members
    assert beliefs[handed.new] == max(beliefs[i] for i in ids[1:])
