"""Operators and autonomy (docs/REFERENCE.md) through `hfsm-run --world none --json --trace --operator FILE`: held arcs, the operator's
answers, autonomy levels, pause/step/resume, replay of a trace's operator records. The machines are
in tests/spec/operator/."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from spec.conformance import Ran, paired

from hfsm.cli.run import main

HERE = Path(__file__).resolve().parent / "operator"


def run(
    capsys: pytest.CaptureFixture[str],
    tmp_path: Path,
    name: str,
    *args: str,
    script: list[dict[str, Any]] | None = None,
    trace: str = "trace.jsonl",
) -> Ran:
    argv = [
        str(HERE / f"{name}.yaml"),
        "--world",
        "none",
        "--json",
        "--quiet",
        "--trace",
        str(tmp_path / trace),
    ]
    if script is not None:
        (tmp_path / "ops.yaml").write_text(json.dumps(script))
        argv += ["--operator", str(tmp_path / "ops.yaml")]
    code = main([*argv, *args])
    out, err = capsys.readouterr()
    path = tmp_path / trace
    records = [json.loads(line) for line in path.read_text().splitlines()] if path.exists() else []
    return Ran(code, json.loads(out) if out.strip() else {}, records, err)


def kinds(ran: Ran, *wanted: str) -> list[tuple[float, str, str, str]]:
    """(t, path below the top, kind, event or do) of the records of these kinds."""
    return [
        (r["t"], "/".join(r["path"][1:]), r["kind"], r.get("event") or r.get("do") or "")
        for r in ran.records
        if r["kind"] in wanted
    ]


def outcome(ran: Ran) -> tuple[str | None, float]:
    return ran.result.get("outcome"), ran.result.get("time")  # type: ignore[return-value]


def test_full_autonomy_holds_nothing(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = run(capsys, tmp_path, "grasp")
    assert (ran.code, outcome(ran)) == (0, ("regrasped", 0.2))
    assert not kinds(ran, "held", "operator")


def test_a_held_arc_with_no_operator_is_blocked_forever_naming_the_hold(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = run(capsys, tmp_path, "grasp", "--autonomy", "low")
    assert ran.code == 1
    assert ran.result["error"] == (
        "blocked forever: robot in grasp/grasp; held: grasp/grasp holds 'failed' (needs autonomy high)"
    )
    held = [r for r in ran.records if r["kind"] == "held"]
    assert held == [
        {
            "t": 0.2,
            "agent": "robot",
            "path": ["grasp", "grasp"],
            "kind": "held",
            "event": "failed",
            "level": "high",
        }
    ]
    assert paired(ran.records)


@pytest.mark.parametrize("level", ["high", "full"])
def test_a_level_at_or_above_the_arcs_does_not_hold(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, level: str
) -> None:
    ran = run(capsys, tmp_path, "grasp", "--autonomy", level)
    assert outcome(ran) == ("regrasped", 0.2)


def test_accept_takes_the_held_arc_in_the_tick_the_answer_arrives(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = run(
        capsys, tmp_path, "grasp", "--autonomy", "off", script=[{"t": 1, "agent": "robot", "do": "accept"}]
    )
    assert (ran.code, outcome(ran)) == (0, ("regrasped", 1.0))
    assert kinds(ran, "held", "operator") == [
        (0.2, "grasp", "held", "failed"),
        (1.0, "grasp", "operator", "accept"),
    ]
    operator = next(r for r in ran.records if r["kind"] == "operator")
    assert operator == {
        "t": 1.0,
        "agent": "robot",
        "path": ["grasp", "grasp"],
        "kind": "operator",
        "do": "accept",
        "event": None,
    }
    assert paired(ran.records)


def test_force_takes_another_event_of_the_held_state(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.5, "agent": "robot", "do": "force", "event": "done"}]
    ran = run(capsys, tmp_path, "grasp", "--autonomy", "low", script=script)
    assert outcome(ran) == ("carried", 0.5)
    assert (0.5, "grasp", "event", "done") in kinds(ran, "event")


def test_force_with_no_hold_acts_on_the_deepest_running_call(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """The deepest call is grasp_object's `reach` (a wait): forcing its `done` ends the grasp early."""
    script = [{"t": 0.1, "agent": "robot", "do": "force", "event": "done"}]
    ran = run(capsys, tmp_path, "grasp", script=script)
    assert outcome(ran) == ("regrasped", 0.1)
    assert (0.1, "grasp/reach", "event", "done") in kinds(ran, "event")
    forced = next(r for r in ran.records if r["kind"] == "operator")
    assert forced["path"] == ["grasp", "grasp", "reach"]


def test_force_of_an_event_the_state_does_not_map_is_written_and_ignored(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.1, "agent": "robot", "do": "force", "event": "failed"}]
    ran = run(capsys, tmp_path, "grasp", script=script)
    assert outcome(ran) == ("regrasped", 0.2)
    forced = next(r for r in ran.records if r["kind"] == "operator")
    assert forced["ignored"] == "'failed' is not an event of grasp/grasp/reach (it maps: done)"


def test_raising_the_level_takes_a_held_arc_at_once(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.7, "do": "autonomy", "level": "high"}]
    ran = run(capsys, tmp_path, "grasp", "--autonomy", "low", script=script)
    assert outcome(ran) == ("regrasped", 0.7)
    record = next(r for r in ran.records if r["kind"] == "operator")
    assert record == {
        "t": 0.7,
        "agent": None,
        "path": [],
        "kind": "operator",
        "do": "autonomy",
        "level": "high",
    }


def test_a_level_still_too_low_keeps_the_hold(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    script = [{"t": 0.7, "do": "autonomy", "level": "low"}]
    ran = run(capsys, tmp_path, "grasp", "--autonomy", "off", script=script)
    assert ran.code == 1 and "holds 'failed'" in ran.result["error"]


def test_lowering_the_level_holds_arcs_from_then_on(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.1, "do": "autonomy", "level": "off"}, {"t": 0.3, "agent": "robot", "do": "accept"}]
    ran = run(capsys, tmp_path, "grasp", script=script)
    assert outcome(ran) == ("regrasped", 0.3)


def test_a_held_timer_lets_the_callee_run_and_not_end_the_state(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    """The timer fires at 0.3 and its arc is held; the grasp ends at 1.0 (let go: the state holds);
    the answer at 1.5 takes `timeout`."""
    script = [{"t": 1.5, "agent": "robot", "do": "accept", "event": "timeout"}]
    ran = run(capsys, tmp_path, "slow_grasp", "--autonomy", "off", script=script)
    assert outcome(ran) == ("gave_up", 1.5)
    assert kinds(ran, "timeout", "held") == [(0.3, "grasp", "timeout", ""), (0.3, "grasp", "held", "timeout")]
    reach = [k for k in kinds(ran, "exit") if k[1] == "grasp/reach"]
    assert reach == [(1.0, "grasp/reach", "exit", "done")]  # the callee ran on, to its own end


def test_accept_naming_another_event_is_ignored(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    script = [{"t": 0.5, "agent": "robot", "do": "accept", "event": "done"}]
    ran = run(capsys, tmp_path, "grasp", "--autonomy", "off", script=script)
    assert ran.code == 1
    record = next(r for r in ran.records if r["kind"] == "operator")
    assert record["ignored"] == "the arc held first is 'failed', not 'done'"


def test_a_machine_timer_above_cancels_the_held_arc(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = run(capsys, tmp_path, "watchdog", "--autonomy", "off")
    assert (ran.code, outcome(ran)) == (0, ("timeout", 0.5))
    assert (0.2, "run/grasp", "held", "failed") in kinds(ran, "held")
    assert paired(ran.records)


def test_an_outer_state_timer_cancels_the_held_arc(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ran = run(capsys, tmp_path, "outer_timer", "--autonomy", "off")
    assert outcome(ran) == ("late", 0.5)
    assert paired(ran.records)


def test_regions_are_answered_in_their_order(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    script = [
        {"t": 0.5, "agent": "robot", "do": "force", "event": "done"},
        {"t": 0.6, "agent": "robot", "do": "accept"},
    ]
    ran = run(capsys, tmp_path, "two", "--autonomy", "off", script=script)
    assert outcome(ran) == ("second", 0.6)  # left forced to carry, right accepted: regrasped
    assert kinds(ran, "held") == [
        (0.2, "hold/left/grasp", "held", "failed"),
        (0.2, "hold/right/grasp", "held", "failed"),
    ]
    ops = [(r["t"], "/".join(r["path"][1:])) for r in ran.records if r["kind"] == "operator"]
    assert ops == [(0.5, "hold/left/grasp"), (0.6, "hold/right/grasp")]


def test_a_join_rule_by_its_target(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = run(
        capsys, tmp_path, "joined", "--autonomy", "low", script=[{"t": 1, "agent": "robot", "do": "accept"}]
    )
    assert outcome(ran) == ("done", 1.0)
    assert kinds(ran, "held") == [(0.2, "both", "held", "join:done")]


def test_a_held_message_stays_unconsumed_and_the_callee_runs_on(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.5, "agent": "a", "do": "accept", "event": "stop"}]
    ran = run(capsys, tmp_path, "listen", "--agents", "a,b", "--autonomy", "low", script=script)
    assert ran.result["agents"]["a"]["outcome"] == "stopped"
    assert ran.result["agents"]["a"]["time"] == 0.5
    assert (0.05, "work", "held", "stop") in kinds(ran, "held")


def test_a_held_message_forced_otherwise_goes_back_to_the_mailbox(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.5, "agent": "a", "do": "force", "event": "done"}]
    ran = run(capsys, tmp_path, "listen", "--agents", "a,b", "--autonomy", "low", script=script)
    assert ran.result["agents"]["a"]["outcome"] == "worked"


def test_pause_step_resume_with_the_clock_standing_still(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [
        {"t": 0.1, "do": "pause"},
        {"t": 0.1, "do": "step"},
        {"t": 0.15, "do": "step"},
        {"t": 0.2, "do": "resume"},
    ]
    ran = run(capsys, tmp_path, "grasp", script=script)
    assert outcome(ran) == ("regrasped", 0.2)  # the same run: a paused clock stands still
    assert [(r["t"], r["do"]) for r in ran.records if r["kind"] == "operator"] == [
        (0.1, "pause"),
        (0.1, "step"),
        (0.15, "step"),
        (0.2, "resume"),
    ]


def test_a_step_while_running_is_ignored(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = run(capsys, tmp_path, "grasp", script=[{"t": 0.1, "do": "step"}])
    record = next(r for r in ran.records if r["kind"] == "operator")
    assert record["ignored"] == "the run is not paused"


def test_a_paused_run_that_nothing_resumes_is_blocked_forever(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.1, "do": "pause"}, {"t": 0.1, "do": "step"}, {"t": 0.5, "do": "resume"}]
    ran = run(capsys, tmp_path, "grasp", script=script)
    assert ran.code == 1
    assert ran.result["error"].startswith("blocked forever: paused at t=0.15 s, and no operator record")
    assert ran.result["time"] == 0.15
    assert paired(ran.records)


def test_pause_at_zero_stops_before_anything_runs(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    script = [{"t": 0, "do": "pause"}, {"t": 0, "do": "resume"}]
    ran = run(capsys, tmp_path, "grasp", script=script)
    assert outcome(ran) == ("regrasped", 0.2)
    assert [r["kind"] for r in ran.records[:3]] == ["run", "operator", "operator"]


def test_a_trace_replays_its_operator_records_byte_for_byte(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [
        {"t": 0.05, "do": "pause"},
        {"t": 0.05, "do": "step"},
        {"t": 0.1, "do": "resume"},
        {"t": 0.1, "agent": "robot", "do": "force", "event": "failed"},  # ignored: not mapped there
        {"t": 0.4, "agent": "robot", "do": "force", "event": "timeout"},
    ]
    first = run(capsys, tmp_path, "grasp", "--autonomy", "off", script=script, trace="first.jsonl")
    run(
        capsys,
        tmp_path,
        "grasp",
        "--autonomy",
        "off",
        "--operator",
        str(tmp_path / "first.jsonl"),
        trace="again.jsonl",
    )
    assert outcome(first) == ("gave_up", 0.4)
    assert (tmp_path / "first.jsonl").read_bytes() == (tmp_path / "again.jsonl").read_bytes()


def test_checks_name_a_bad_autonomy_key_and_level(capsys: pytest.CaptureFixture[str]) -> None:
    code = main([str(HERE / "bad_autonomy.yaml"), "--check"])
    err = capsys.readouterr().err
    assert code == 2
    assert (
        "bad_autonomy.yaml:6:16: error[E355]: autonomy names 'dnoe', which is not an event of state 'work'"
        in err
    )
    assert "did you mean 'done'?" in err
    assert (
        "bad_autonomy.yaml:6:34: error[E356]: autonomy level 'hihg' is not one of off, low, high, full; did you mean 'high'?"
        in err
    )


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("- {t: 1, do: acept, agent: robot}", "2:14: error[E360]: do must be one of"),
        ("- {t: -1, do: pause}", "1:7: error[E360]: t must be a number of seconds >= 0"),
        (
            "- {t: 1, do: accept, agent: robt}",
            "error[E360]: no agent named 'robt' in this run; did you mean 'robot'?",
        ),
        ("- {t: 1, do: force, agent: robot}", "error[E360]: 'force' needs the event to take"),
        (
            "- {t: 1, do: autonomy, level: hihg}",
            "error[E360]: 'autonomy' needs a level, one of off, low, high, full",
        ),
        ("- {t: 1, do: pause, when: 2}", "error[E360]: unknown key 'when'"),
        ("{t: 1}", "1:1: error[E360]: an operator script is a list"),
    ],
)
def test_a_bad_operator_file_is_exit_2_at_its_position(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, text: str, message: str
) -> None:
    script = tmp_path / "ops.yaml"
    script.write_text("\n" + text if "acept" in text else text)
    code = main([str(HERE / "grasp.yaml"), "--world", "none", "--operator", str(script)])
    err = capsys.readouterr().err
    assert code == 2
    assert message in err
    assert "Traceback" not in err


def test_a_breakpoint_pauses_at_the_start_of_the_next_tick(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    script = [{"t": 0.05, "do": "resume"}]
    ran = run(capsys, tmp_path, "grasp", "--break", "enter:grasp/reach", script=script)
    assert outcome(ran) == ("regrasped", 0.2)
    ops = [(r["t"], r["do"], r.get("break")) for r in ran.records if r["kind"] == "operator"]
    assert ops == [(0.05, "pause", "enter:grasp/reach"), (0.05, "resume", None)]


def test_a_bad_breakpoint_is_exit_2(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ran = run(capsys, tmp_path, "grasp", "--break", "entre:grasp")
    assert ran.code == 2 and "KIND:PATTERN[@AGENT]" in ran.err


def test_the_operator_sends_an_agent_a_message(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    script = [{"t": 0.5, "agent": "a", "do": "message", "message": "stop", "data": {"why": "<b>"}}]
    ran = run(capsys, tmp_path, "listen", "--agents", "a", script=script)
    assert outcome(ran) == ("stopped", 0.5)
    received = next(r for r in ran.records if r["kind"] == "receive")
    assert (received["t"], received["sender"], received["data"]) == (0.5, "operator", {"why": "<b>"})
