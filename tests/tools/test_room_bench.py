from __future__ import annotations

import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_sim.roomgen import STRATA, draw  # noqa: E402
from tools.room.experiments import DEVELOP, HELD, QUICK, Config, trials  # noqa: E402
from tools.room.report import cause, verdict, wilson, write  # noqa: E402
from tools.room.trials import RoomLine, cleared_at, measure, phase, run_room_trial  # noqa: E402
from tools.sweep import run_sweep  # noqa: E402


def test_the_campaign_draws_every_stratum_from_the_generator_on_held_seeds() -> None:
    every = trials(Config())
    assert len(every) >= 200
    for stratum in STRATA:
        rooms = [t for t in every if t.experiment == stratum]
        assert [t.seed for t in rooms] == list(range(HELD, HELD + 25))
        assert all(t.scenario == draw(t.seed, stratum) and t.max_time == 2100.0 for t in rooms)
    assert max(DEVELOP) < HELD  # the measure never sees a seed used while developing
    assert [t.experiment for t in trials(Config(rooms=2, strata=("loss", "walls")))] == ["loss"] * 2 + ["walls"] * 2


def test_wilson_interval() -> None:
    lo, hi = wilson(38, 40)
    assert lo == pytest.approx(0.835, abs=0.002) and hi == pytest.approx(0.986, abs=0.002)
    assert wilson(0, 0) == (0.0, 1.0)
    assert wilson(10, 10)[1] == 1.0 and wilson(0, 10)[0] == 0.0


def _event(t: float, agent: str, state: str, **values: Any) -> dict[str, Any]:
    return {"t": t, "agent": agent, "path": ["clear_room", state], "kind": "event", "event": "done",
            "vars": values}


def test_the_trace_gives_the_clearing_time_and_the_failure_phase() -> None:
    line = RoomLine()
    carry = {"table": "table1", "role": "leader", "partner": "r2", "outcome": "at_wall"}
    records = [
        _event(1.0, "r1", "assign", job={"role": "leader"}), _event(1.0, "r2", "assign", job={"role": "assistant"}),
        _event(1.0, "r3", "assign", job={"role": "spare"}), _event(1.0, "r4", "assign", job={"role": "leader"}),
        {"t": 20.0, "agent": "r1", "path": ["clear_room", "work", "carry", "lift", "lift"], "kind": "enter",
         "do": "lift_table"},
        {"t": 30.0, "agent": "r2", "path": ["clear_room"], "kind": "failed"},
        _event(90.0, "r1", "finished", carries=[carry]),
        _event(95.0, "r4", "give_up", carries=[{**carry, "table": "table2", "outcome": "dropped"}]),
        _event(140.0, "r4", "finished", carries=[{**carry, "table": "table2"}]),
    ]  # fmt: skip
    for record in records:
        line.write(record)
    assert cleared_at(line.carries, ["table1", "table2"]) == 140.0
    assert cleared_at(line.carries[:2], ["table1", "table2"]) is None
    assert line.failed == {"r2": 30.0}
    assert phase(line, "r1", 25.0) == "not reached"
    line.failed.update(r1=25.0, r3=5.0, r4=10.0)
    assert [phase(line, r, at) for r, at in (("r1", 25.0), ("r3", 5.0), ("r4", 10.0), ("r1", 100.0))] == [
        "mid-carry", "spare", "before lift", "after its table"]


SCORE = {"table_wall_distances": [0.01, 0.9], "table_wall_distance": 0.9, "robot_collisions": 0, "dropped": False}
TABLES = {"tables": [{"id": "table1"}, {"id": "table2"}], "failures": []}
WHY = "table2 needs two robots to lift it and 1 robot left alive (r1)"


def test_a_team_that_ends_stuck_before_the_limit_ended_honestly() -> None:
    line = RoomLine()
    line.write(_event(300.0, "r1", "assign", job={"role": "stuck", "stuck": "table2", "why": WHY}))
    honest = measure(line, SCORE, TABLES, {"r1": "stuck", "r2": None}, 310.0, None)
    assert honest["honest"] and not honest["cleared"] and honest["stuck"] == [WHY]
    assert verdict(honest) == "honest"
    timed_out = measure(line, SCORE, TABLES, {"r1": None, "r2": None}, 2100.0, "stopped at --max-time 2100")
    assert not timed_out["honest"] and verdict(timed_out) == "failed"
    touched = measure(line, {**SCORE, "robot_collisions": 2}, TABLES, {"r1": "stuck"}, 310.0, None)
    assert not touched["honest"]
    cleared = measure(RoomLine(), {**SCORE, "table_wall_distances": [0.01, 0.02], "robot_collisions": 1}, TABLES,
                      {"r1": "cleared"}, 200.0, None)
    assert cleared["cleared"] and not cleared["success"] and verdict(cleared) == "contacts"


def _result(trial: int, stratum: str, success: bool, **more: Any) -> dict[str, Any]:
    return {"trial": trial, "experiment": stratum, "x": stratum, "seed": 10000 + trial, "k": 2, "n": 5,
            "loss": 0.0, "room": [8.0, 6.0], "cleared": success, "success": success, "honest": False,
            "stuck": [], "clear_time": 120.0 if success else None, "time": 130.0 if success else 2100.0,
            "error": None if success else "stopped at --max-time 2100", "distances": [0.01, 0.01 if success else 0.9],
            "dropped": False, "collisions": 0, "carries": [], "wall": 40.0 + trial, "failures": [], **more}


def test_the_report_gives_each_stratum_and_every_failing_room_with_its_cause(tmp_path: Path) -> None:
    results = [_result(0, "open", True), _result(1, "open", True), _result(2, "walls", False),
               _result(3, "walls", True, collisions=0),
               _result(4, "failures", False, honest=True, stuck=[WHY], time=400.0, error=None,
                       failures=[{"robot": "r2", "at": 50.0, "phase": "mid-carry"}]),
               _result(5, "close", False, cleared=True, collisions=3, clear_time=200.0)]
    doc = tmp_path / "ROOM.md"
    doc.write_text("# Room\n\nbefore\n<!-- room_bench:start -->\nold\n<!-- room_bench:end -->\nafter\n")
    write(results, doc, tmp_path / "fig", "tools/room_bench.py --rooms 2", 600.0, 2, "load average 1.00")
    text = doc.read_text(encoding="utf-8")
    assert text.startswith("# Room\n\nbefore\n<!-- room_bench:start -->") and text.endswith("end -->\nafter\n")
    assert "old" not in text
    assert "**All rooms: 3 of 6 (50 %; 95 % Wilson 19-81 %) successes**; honest ends 1" in text
    assert "| open | 2 | 2 (100 %) | 34-100 % | 0 |" in text
    assert "| walls | 2 | 1 (50 %) | 9-91 % |" in text
    assert "median wall s" in text and "Wall time of one room: median 42 s" in text
    assert "- trial 2 (walls, seed 10002, failed): tables off their walls:" in text
    assert f"- trial 4 (failures, seed 10004, honest): stuck: {WHY}" in text
    assert "- trial 5 (close, seed 10005, contacts): 3 robot-robot contacts" in text
    assert "mid-carry: 0/1" in text
    assert sorted(p.name for p in (tmp_path / "fig").iterdir()) == ["wall_vs_n.png"]
    assert "stopped at the limit, 2100 s" in cause(results[2])


@pytest.mark.slow
def test_results_are_the_same_on_one_and_two_workers() -> None:
    specs = [replace(t, max_time=8.0) for t in trials(QUICK)]
    one = run_sweep(run_room_trial, specs, workers=1)
    two = run_sweep(run_room_trial, specs, workers=2)
    assert [r["trial"] for r in one] == [0, 1]
    assert [{k: v for k, v in r.items() if k != "wall"} for r in one] == [
        {k: v for k, v in r.items() if k != "wall"} for r in two]
    assert [r["experiment"] for r in one] == ["open", "failures"]
    assert all(r["collisions"] == 0 and not r["cleared"] for r in one)


def test_a_table_falling_from_a_robot_failing_mid_carry_is_the_failures_not_the_teams() -> None:
    line = RoomLine()
    for record in (
        _event(1.0, "r1", "assign", job={"role": "leader"}),
        {"t": 20.0, "agent": "r1", "path": ["clear_room", "work", "carry", "lift", "lift"], "kind": "enter",
         "do": "lift_table"},
        {"t": 30.0, "agent": "r1", "path": ["clear_room"], "kind": "failed"},
    ):
        line.write(record)
    at_walls = {"table_wall_distances": [0.01, 0.02], "table_wall_distance": 0.02, "robot_collisions": 0}
    scenario = {"tables": [{"id": "table1"}, {"id": "table2"}], "failures": [{"robot": "r1", "at": 30.0}]}
    dropped = measure(line, {**at_walls, "dropped": True}, scenario, {}, 200.0, None)
    assert dropped["cleared"] and dropped["dropped_by_failure"] and dropped["failure"]["phase"] == "mid-carry"
    before_lift = {**scenario, "failures": [{"robot": "r1", "at": 10.0}]}
    line.failed["r1"] = 10.0
    assert not measure(line, {**at_walls, "dropped": True}, before_lift, {}, 200.0, None)["cleared"]
    assert not measure(line, {**at_walls, "dropped": True}, {"tables": scenario["tables"]}, {}, 200.0,
                       None)["cleared"]
