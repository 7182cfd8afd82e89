"""What `--trace` writes for the SPEC's examples (section 10's kinds, 11's paths, 13's retry events)."""

from __future__ import annotations

from pathlib import Path

import pytest
from spec.conformance import hfsm_run


def test_paths_below_a_parallel_state_go_through_the_region(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = hfsm_run(capsys, tmp_path, "search", ["--agents", "finder"])
    entered = [p for _, p, _ in ran.events("finder", "enter")]
    assert entered[:5] == ["", "search", "search/explore", "search/explore/explore", "search/detect"]
    assert "search/detect/look" in entered and "search/head/turn" in entered
    # the join is taken at 0.5 s: every region still running (explore, head) is left then
    assert {(t, p) for t, p, _ in ran.events("finder", "exit") if p.count("/") == 1} == {
        (0.5, "search/explore"),
        (0.5, "search/detect"),
        (0.5, "search/head"),
    }


def test_a_retry_writes_an_event_and_does_not_reenter_the_state(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = hfsm_run(capsys, tmp_path, "navigate")
    retries = [(r["t"], r["attempt"]) for r in ran.records if r.get("event") == "retry"]
    assert retries == [(1.0, 2), (3.5, 3)]
    assert [t for t, p, _ in ran.events("robot", "enter") if p == "navigate"] == [0.0]
    assert [t for t, p, _ in ran.events("robot", "enter") if p == "navigate/drive"] == [0.0, 2.5, 5.0]
    assert [(t, p) for t, p, _ in ran.events("robot", "error")] == [(3.5, "navigate/crash")]


def test_receive_when_a_message_enters_the_mailbox_and_its_consumption_an_event(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = hfsm_run(capsys, tmp_path, "early", ["--agents", "a,b"])
    assert [(r["t"], r["message"], r["sender"]) for r in ran.records if r["kind"] == "receive"] == [
        (0.05, "go", "a")
    ]
    assert ran.events("b", "event")[-1] == (0.2, "listen", "go")


def test_timers_write_a_timeout_record(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = hfsm_run(capsys, tmp_path, "span")
    timeouts = [(r["t"], r["timer"]) for r in ran.records if r["kind"] == "timeout"]
    assert timeouts == [(0.4, "state"), (0.65, "state")]
    watchdog = hfsm_run(capsys, tmp_path, "watchdog")
    assert [(r["t"], r["timer"], r["path"]) for r in watchdog.records if r["kind"] == "timeout"] == [
        (0.5, "machine", ["watchdog"])
    ]


def test_a_failed_agent_writes_failed_and_leaves_every_state(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = hfsm_run(capsys, tmp_path, "team", ["--agents", "a,b,c", "--fail", "c@1"])
    assert [(r["t"], r["reason"]) for r in ran.records if r["kind"] == "failed"] == [(1.0, "--fail")]
    assert [r for r in ran.records if r["agent"] == "c"][-1]["kind"] == "exit"
    assert not [r for r in ran.records if r["agent"] == "c" and r["t"] > 1.0]


def test_a_watch_arc_is_an_event_in_its_tick(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = hfsm_run(capsys, tmp_path, "watches")
    arcs = [(t, p) for t, p, e in ran.events("robot", "event") if p in ("entry", "race", "last")]
    assert arcs == [(0.0, "entry"), (0.3, "race"), (2.0, "last")]
    assert not [p for _, p, _ in ran.events("robot", "enter") if p.startswith("entry/")], "never started"
