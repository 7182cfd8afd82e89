"""hfsm-verify's command line: machines stood in for, bad input (exit 2, positioned), and the
counterexample as hfsm-monitor reads it and hfsm-run replays it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from verify_run import DATA, EXAMPLES, MACHINES, replay, verify

from hfsm.cli import monitor
from hfsm.cli import verify as verify_cli


def test_a_machine_stood_in_for_may_end_with_any_outcome(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    file = DATA / "watch_join.yaml"
    args = ("--goal", "success", "--stand-in", "counter")
    code, verdict = verify(capsys, file, *args, out=tmp_path / "slow.jsonl")
    assert (code, verdict["kind"]) == (1, "failure_outcome")  # a counter as slow as the state's timer
    assert "counter of robot at watch_join/work/count ended 'counted' after 200 ticks" in verdict["stderr"]
    args = ("--goal", "success", "--stand-in", "reach_once")
    code, verdict = verify(capsys, file, *args, out=tmp_path / "ce.jsonl")
    assert (code, verdict["kind"]) == (1, "failure_outcome")
    assert "reach_once of robot at watch_join/reach ended" in verdict["stderr"]
    schedule = json.loads((tmp_path / "ce.jsonl").read_text().splitlines()[0])["verify"]
    assert schedule["stand_ins"] == ["reach_once"]
    assert any(c["what"].startswith("reach_once of robot") for c in schedule["choices"])


def test_a_counterexample_of_a_machine_using_a_worlds_primitives_replays_in_world_none(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """`lift_table` is a primitive of the simulated world only: hfsm-verify stands it in, and so
    does the replay in world `none` (it once stopped at E300, the primitive not of that world)."""
    file = MACHINES / "synchronised_lift_table.yaml"
    roles = ("--agent-param", "r1:role=leader", "--agent-param", "r2:role=assistant")
    args = ("--agents", "r1,r2", *roles, "--param", "patience=5", "--goal", "success")
    code, verdict = verify(capsys, file, *args, out=tmp_path / "ce.jsonl")
    assert (code, verdict["kind"]) == (1, "failure_outcome")
    assert "lift_table of r1" in verdict["stderr"]
    assert replay(file, tmp_path / "ce.jsonl", tmp_path / "again.jsonl") == 0
    assert (tmp_path / "again.jsonl").read_bytes() == (tmp_path / "ce.jsonl").read_bytes()


def test_bad_input_is_exit_2_with_every_problem_at_its_place(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    props = tmp_path / "props.yaml"
    props.write_text(
        'never_together: [lfit, walk]\nleft_within: {meet: -1}\nat_end: "open(1)"\nsometimes: 1\n'
    )
    meet = str(EXAMPLES / "meet.yaml")
    assert verify_cli.main([meet, "--agents", "a,b", "--props", str(props)]) == 2
    err = [line for line in capsys.readouterr().err.splitlines() if "error[" in line]  # not the snippets
    assert err == [
        f"{props}:1:18: error[E371]: no state 'lfit' in the machines; did you mean 'lift'?",
        f"{props}:2:21: error[E370]: -1: a number of seconds > 0",
        f"{props}:3:9: error[E372]: at_end: only abs, all, any, len, max, min, sorted, sum may be called",
        f"{props}:4:1: error[E370]: unknown property 'sometimes'",
    ]
    assert verify_cli.main([meet, "--agents", "a,b", "--stand-in", "mete"]) == 2
    assert "did you mean 'meet'?" in capsys.readouterr().err
    assert verify_cli.main([meet, "--agents", "a,b", "--agent-param", "c:walk=1"]) == 2
    assert verify_cli.main([meet, "--loss", "-1"]) == 2
    for scope in ("p1:a,c", "p1", "P1:a,b"):
        assert verify_cli.main([meet, "--agents", "a,b", "--scope", scope]) == 2
    assert "did you mean 'a'?" not in capsys.readouterr().err
    assert verify_cli.main([meet, "--agents", "a,b", "--scope", "p:a,b", "--scope", "q:b"]) == 2
    assert "b is already in scope 'p'" in capsys.readouterr().err
    assert not list(tmp_path.glob("*.jsonl")) and not (EXAMPLES / "meet.ce.jsonl").exists()


def test_the_monitor_reads_a_counterexample(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _ = verify(
        capsys, DATA / "ping_once.yaml", "--agents", "a,b", "--loss", "1", out=tmp_path / "ce.jsonl"
    )
    assert code == 1
    records = monitor.read_trace(tmp_path / "ce.jsonl")
    assert records[0]["kind"] == "schedule" and records[0]["path"] == []
    assert monitor.top_name(records, tmp_path / "ce.jsonl") == "ping_once"
    assert {r["agent"] for r in records[1:]} == {"a", "b"}


def test_a_bad_values_file_is_exit_2_with_every_problem_at_its_place(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    values = tmp_path / "values.yaml"
    values.write_text(
        "stand_in: {}\n"
        "stand_ins:\n"
        "  sense: [{after: 1, outcom: measured}, {outputs: 3}]\n"
        "  look: {by_agent: {a: 1}}\n"
    )
    args = [str(DATA / "measure.yaml"), "--stand-in", "sense", "--values", str(values)]
    assert verify_cli.main(args) == 2
    err = [line for line in capsys.readouterr().err.splitlines() if "error[" in line]
    assert err == [
        f"{values}:1:1: error[E373]: 'stand_in': outputs, inputs or stand_ins, each a mapping; did you mean 'stand_ins'?",
        f"{values}:3:22: error[E373]: 'outcom': not a key of a step; did you mean 'outcome'?",
        f"{values}:3:51: error[E373]: outputs: a mapping",
        f"{values}:4:24: error[E373]: a step: a mapping of after, outcome, outputs",
    ]
