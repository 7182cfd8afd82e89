"""A tick's time as text, from its table (TickTimes) or by formatting (seconds_text), is the JSON of
RunClock.time: `round(k * dt, 9)` as `json.dumps` writes it."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from hfsm.runtime.ticktime import TickTimes, seconds_text
from hfsm.trace import encode

# a dt of at most 9 decimals (a table), the CLI's bounds, and some that are not (no table)
DTS = (
    st.integers(1, 10**10).map(lambda ns: ns / 10**9)
    | st.integers(1, 10**5).map(lambda us: us / 10**6)  # periods of at most 1e6 ticks: tables of few
    | st.sampled_from([0.05, 0.001, 10.0, 0.3, 0.007, 1e-4, 0.123456789, 1 / 120, 1 / 3, 5e-5, 2.5e-10])
    | st.floats(1e-6, 100.0)
)
TICKS = st.integers(0, 10**12) | st.integers(0, 10**5)


@given(TICKS, DTS)
def test_a_ticks_time_from_its_table_is_as_json_writes_it(tick: int, dt: float) -> None:
    assert TickTimes(dt).text(tick) == encode(round(tick * dt, 9))


@given(st.integers(0, 10**12), st.floats(1e-6, 100.0) | st.sampled_from([0.05, 0.01, 0.1, 1 / 120, 0.001, 0.3]))
def test_a_ticks_seconds_are_written_as_json_writes_them(ticks: int, dt: float) -> None:
    assert seconds_text(ticks, dt) == encode(round(ticks * dt, 9))


def test_a_dt_of_few_decimals_has_a_short_table() -> None:
    times = TickTimes(0.05)
    assert (times.period, times.whole, len(times.table)) == (20, 1, 20)
    assert [times.text(k) for k in (0, 1, 20, 21, 2469)] == ["0.0", "0.05", "1.0", "1.05", "123.45"]
    assert TickTimes(1 / 120).table == []  # not 9 decimals: formatted each time


@given(TICKS, DTS, st.integers(1, 70))
def test_the_heads_of_the_next_ticks_hold_their_times(tick: int, dt: float, count: int) -> None:
    heads = TickTimes(dt).heads(tick, count)
    assert 1 <= len(heads) <= count
    assert heads == ['{"t": ' + encode(round((tick + i) * dt, 9)) for i in range(len(heads))]
