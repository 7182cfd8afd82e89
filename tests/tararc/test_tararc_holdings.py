"""The pure steps of TARARC's state exchange (hfsm_behaviours/tararc/holdings.py)."""

from __future__ import annotations

import random

from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.tararc import holdings

TEAM = ["r0", "r1", "r2", "r3"]


def test_a_copy_merged_adds_its_robots_and_what_the_sender_says_it_holds() -> None:
    hold = holdings.holding("r0", {"x": 0}, TEAM, start=0, quiet=None)
    new, more = holdings.merge(hold, "r1", {"held": {"r1": {"x": 1}, "r2": {"x": 2}}, "team": TEAM}, tick=3)
    assert more and sorted(new["held"]) == ["r0", "r1", "r2"] and new["says"] == {"r1": ["r1", "r2"]}
    assert hold["held"] == {"r0": {"x": 0}}  # the holding given is left as it was
    again, more = holdings.merge(new, "r2", {"held": {"r2": {"x": 2}}}, tick=4)
    assert not more and again["last"] == {"r1": 3, "r2": 4}


def test_copies_from_outside_the_team_and_robots_outside_it_are_dropped() -> None:
    hold = holdings.holding("r0", {}, ["r0", "r1"], start=0, quiet=None)
    new, more = holdings.merge(hold, "r9", {"held": {"r9": {}}}, tick=1)
    assert not more and new["held"] == {"r0": {}} and new["says"] == {}
    new, more = holdings.merge(hold, "r1", {"held": {"r1": {}, "r9": {}}}, tick=1)
    assert more and sorted(new["held"]) == ["r0", "r1"]
    assert holdings.merge(hold, "r1", {"held": "nonsense"}, tick=1)[1] is False


def test_agreed_when_every_teammate_says_it_holds_the_same() -> None:
    hold = holdings.holding("r0", {}, ["r0", "r1"], start=0, quiet=None)
    assert not holdings.agreed(hold, 0)
    hold, _ = holdings.merge(hold, "r1", {"held": {"r1": {}}}, tick=1)
    assert not holdings.agreed(hold, 1)  # r1 does not hold r0's yet
    hold, _ = holdings.merge(hold, "r1", {"held": {"r0": {}, "r1": {}}}, tick=2)
    assert holdings.agreed(hold, 2) and holdings.wake(hold, 2) is None


def test_a_silent_teammate_is_neither_waited_for_nor_asked_and_wake_says_when() -> None:
    hold = holdings.holding("r0", {}, ["r0", "r1", "r2"], start=0, quiet=20)
    hold, _ = holdings.merge(hold, "r1", {"held": {"r0": {}, "r1": {}}}, tick=1)
    assert not holdings.agreed(hold, 19) and holdings.wake(hold, 19) == 1  # r2 silent from the start at 20
    assert holdings.agreed(hold, 20)
    assert holdings.results(hold, 20)["talking"] == ["r1"]


def test_an_open_robot_takes_the_team_a_teammate_met() -> None:
    hold = holdings.holding("r0", {}, None, start=0, quiet=10)
    assert holdings.said(hold) == {"held": {"r0": {}}}
    hold, _ = holdings.merge(hold, "r1", {"held": {"r1": {}}, "team": ["r0", "r1", "r2"]}, tick=1)
    assert hold["team"] == ["r1", "r2"]
    assert holdings.said(hold)["team"] == ["r0", "r1", "r2"]


COPIES = st.lists(st.tuples(st.sampled_from(TEAM[1:]), st.sets(st.sampled_from(TEAM))), max_size=8)


@given(COPIES, st.randoms())
def test_the_robots_held_do_not_depend_on_the_order_copies_come_in(copies: list[tuple[str, set[str]]],
                                                                   rnd: random.Random) -> None:
    def held(order: list[tuple[str, set[str]]]) -> list[str]:
        hold = holdings.holding("r0", {}, TEAM, start=0, quiet=None)
        for tick, (sender, robots) in enumerate(order):
            hold, _ = holdings.merge(hold, sender, {"held": {r: {} for r in robots}}, tick)
        return sorted(hold["held"])

    assert held(copies) == held(rnd.sample(copies, len(copies)))
