"""Scopes (docs/REFERENCE.md#scopes) through `hfsm-run --world none --json --trace`: pairs running one handshake in
one run, nested scopes, the mailbox under scopes, `on:` arcs, `to: all`, and run-time errors."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from tests.spec.conformance import hfsm_run, paired


def agent(outcome: str, time: float, **outputs: Any) -> dict[str, Any]:
    return {"outcome": outcome, "outputs": outputs, "time": time}


def test_two_pairs_run_one_handshake_each_under_its_own_scope(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = hfsm_run(capsys, tmp_path, "scope_pairs", ["--agents", "a,b,c,d"])
    assert ran.code == 0, ran.err

    def shook(me: str, mate: str, pair: str) -> dict[str, Any]:
        everyone = [x for x in "abcd" if x != me]
        return agent(
            "done", 0.1, **{"from": mate}, met=[mate], scope=pair, mates=[mate], tag=pair,
            outside="", everyone=everyone,
        )  # fmt: skip

    assert ran.result == {
        "agents": {
            "a": shook("a", "b", "pair_ab"),
            "b": shook("b", "a", "pair_ab"),
            "c": shook("c", "d", "pair_cd"),
            "d": shook("d", "c", "pair_cd"),
        }
    }
    sends = [(r["agent"], r["message"], r["to"]) for r in ran.records if r["kind"] == "send"]
    assert sends == [
        ("a", "pair_ab/hello", "others"),
        ("b", "pair_ab/hello", "others"),
        ("c", "pair_cd/hello", "others"),
        ("d", "pair_cd/hello", "others"),
    ]
    received = sorted((r["agent"], r["message"], r["sender"]) for r in ran.records if r["kind"] == "receive")
    assert received == [
        ("a", "pair_ab/hello", "b"),
        ("b", "pair_ab/hello", "a"),
        ("c", "pair_cd/hello", "d"),
        ("d", "pair_cd/hello", "c"),
    ]
    assert paired(ran.records)


def test_nested_scopes_qualify_from_the_outside_in(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = hfsm_run(capsys, tmp_path, "scope_nested", ["--agents", "a,b,c,d"])
    assert ran.code == 0, ran.err
    scopes = {name: entry["outputs"]["scope"] for name, entry in ran.result["agents"].items()}
    assert scopes == {"a": "room/pair_ab", "b": "room/pair_ab", "c": "room/pair_cd", "d": "room/pair_cd"}
    froms = {name: entry["outputs"]["from"] for name, entry in ran.result["agents"].items()}
    assert froms == {"a": "b", "b": "a", "c": "d", "d": "c"}
    messages = {r["message"] for r in ran.records if r["kind"] in ("send", "receive")}
    assert messages == {"room/pair_ab/hello", "room/pair_cd/hello"}


def test_a_message_of_another_scope_waits_in_the_mailbox(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = hfsm_run(capsys, tmp_path, "scope_mailbox", ["--agents", "a,b"])
    assert ran.code == 0, ran.err
    for name in "ab":
        assert ran.result["agents"][name] == agent("done", 0.1, inner="pair", outer="plain")
    # the plain hello came first, yet the scoped wait took the scoped one; the plain one after
    a_events = [(t, p, e) for t, p, e in ran.events("a", "event") if e.endswith("received")]
    assert a_events == [(0.05, "shake/listen", "received"), (0.1, "after", "received")]


def test_message_arcs_and_to_all_under_a_scope(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = hfsm_run(capsys, tmp_path, "scope_stop", ["--agents", "a,b,c"])
    assert ran.code == 0, ran.err
    outcomes = {name: (e["outcome"], e["time"]) for name, e in ran.result["agents"].items()}
    # a told duo (itself too, `to: all`): a and b stop in the next tick, c in solo never hears it
    assert outcomes == {"a": ("stopped", 0.05), "b": ("stopped", 0.05), "c": ("done", 1.0)}
    stops = [(r["agent"], r["event"]) for r in ran.records if r["kind"] == "event" and r["event"].endswith("/stop")]
    assert stops == [("a", "duo/stop"), ("b", "duo/stop")]


@pytest.mark.parametrize(
    ("case", "words"),
    [
        ("unknown_agent", "unknown_agent: scope 'duo': no agent named 'zed' in the run"),
        ("bad_name", "bad_name: scope: name 'Duo a' is not a name"),
        ("not_a_list", "not_a_list: scope 'duo': agents must be a list of agent ids, not 'a'"),
        ("send_outside", "send_outside: send: no agent named 'c' in scope 'duo' (agents: b, a)"),
        ("barrier_outside", "barrier_outside: barrier 'meet': no agent named 'c' in scope 'duo'"),
    ],
)
def test_bad_scopes_are_errors_where_they_are_met(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, case: str, words: str
) -> None:
    ran = hfsm_run(capsys, tmp_path, "scope_errors", ["--agents", "a,b,c", "--param", f"case={case}"])
    assert ran.code == 1
    assert words in ran.result["error"]
    assert "Traceback" not in ran.err
