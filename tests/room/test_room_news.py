"""The room team's news as data (hfsm_behaviours/room/news.py): merged in any order, the same."""

from __future__ import annotations

import random

from hypothesis import given
from hypothesis import strategies as st

from hfsm_behaviours.room import news

SAID = st.fixed_dictionaries({
    "lost": st.lists(st.sampled_from(["r2", "r3"]), max_size=2),
    "done": st.lists(st.sampled_from(["table1", "table2"]), max_size=2),
    "seen": st.dictionaries(st.sampled_from(["table1"]), st.fixed_dictionaries(
        {"x": st.integers(0, 3), "y": st.integers(0, 3), "t": st.integers(0, 3), "by": st.sampled_from(["r2", "r3"])})),
})


def start() -> dict[str, object]:
    return news.news_of("r1", ["r1", "r2", "r3"], {}, {}, tick=0, quiet=100)


@given(st.lists(st.tuples(st.sampled_from(["r2", "r3"]), SAID), max_size=6), st.randoms())
def test_heartbeats_merged_in_any_order_give_the_same_news(beats: list[tuple[str, dict[str, object]]],
                                                           rnd: random.Random) -> None:
    def heard(order: list[tuple[str, dict[str, object]]]) -> dict[str, object]:
        state = start()
        for sender, said in order:
            state = news.hear(state, sender, said, None, None, tick=1)
        return news.told(news.settle(state, 1)[0])

    assert heard(beats) == heard(rnd.sample(beats, len(beats)))


def test_silence_makes_a_robot_lost_and_wake_says_when() -> None:
    state = news.hear(start(), "r2", {}, {"x": 1.0, "y": 0.0}, {"x": 0.0, "y": 0.0, "yaw": 0.0}, tick=30)
    assert news.wake(state, 50) == 50  # r3, heard at 0, falls silent at 100
    state, changed = news.settle(state, 100)
    assert changed and state["lost"] == ["r3"] and news.told(state)["where"] == {"r2": [1.0, 0.0]}
    assert news.settle(start(), 99) == (start(), False)
