from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hfsm_sim.radio import Radio

times = st.lists(st.floats(min_value=0.0, max_value=100.0, allow_nan=False), min_size=1,
                 max_size=30)


@given(times, st.floats(min_value=0.0, max_value=2.0), st.integers(0, 2**31))
def test_latency_is_respected_and_nothing_is_duplicated(sent: list[float], latency: float,
                                                        seed: int) -> None:
    radio = Radio(latency_s=latency, loss=0.0, seed=seed)
    for index, t in enumerate(sorted(sent)):
        radio.send("r1", "r2", (index, t), t)
    received: list[tuple[int, float]] = []
    for step in range(0, 1100):
        now = step * 0.1
        for sender, to, payload in radio.deliver(now):
            assert (sender, to) == ("r1", "r2")
            assert payload[1] + latency <= now + 1e-6
            received.append(payload)
    assert [index for index, _ in received] == list(range(len(sent)))


@given(st.floats(min_value=0.0, max_value=1.0), st.integers(0, 2**31))
def test_lost_messages_never_arrive_and_loss_is_seeded(loss: float, seed: int) -> None:
    outcomes = []
    for _ in range(2):
        radio = Radio(latency_s=0.05, loss=loss, seed=seed)
        kept = [radio.send("a", "*", n, 0.0) for n in range(50)]
        delivered = [payload for _, _, payload in radio.deliver(1e9)]
        assert delivered == [n for n, ok in enumerate(kept) if ok]
        assert radio.deliver(1e12) == []
        outcomes.append(kept)
    assert outcomes[0] == outcomes[1]


def test_total_loss_and_no_loss() -> None:
    lossy = Radio(0.0, 1.0, seed=1)
    assert not lossy.send("a", "b", "x", 0.0)
    assert lossy.deliver(10.0) == []
    clean = Radio(0.2, 0.0, seed=1)
    clean.send("a", "b", "x", 1.0)
    assert clean.deliver(1.1) == []
    assert clean.deliver(1.2) == [("a", "b", "x")]


def test_order_is_arrival_then_send_order() -> None:
    radio = Radio(0.1, 0.0)
    radio.send("b", "a", 2, 0.5)
    radio.send("a", "b", 1, 0.2)
    radio.send("c", "a", 3, 0.5)
    assert [m[2] for m in radio.deliver(1.0)] == [1, 2, 3]


def test_bad_parameters() -> None:
    with pytest.raises(ValueError):
        Radio(-1.0, 0.0)
    with pytest.raises(ValueError):
        Radio(0.1, 1.5)
