from __future__ import annotations

from hfsm.monitor.hub import Hub, MonitorSink


def test_records_come_through_the_queue_in_order_and_the_end_is_marked() -> None:
    hub = Hub(live=True)
    sink = MonitorSink(hub)
    for t in range(3):
        sink.write({"t": t, "path": ["m"], "kind": "enter"})
    assert not hub.ended
    assert [r["t"] for r in hub.since(0)] == [0, 1, 2]
    assert [r["t"] for r in hub.since(2)] == [2]
    sink.close()
    hub.drain()
    assert hub.ended


def test_a_full_queue_drops_and_counts_instead_of_blocking_the_run() -> None:
    hub = Hub(live=True, size=2)
    sink = MonitorSink(hub)
    for t in range(5):
        sink.write({"t": t, "path": ["m"], "kind": "enter"})
    assert hub.dropped == 3
    assert len(hub.since(0)) == 2


def test_a_replay_hub_holds_the_trace_and_has_ended() -> None:
    hub = Hub([{"t": 0, "path": ["m"], "kind": "enter"}])
    assert hub.ended and not hub.live and len(hub.since(0)) == 1
