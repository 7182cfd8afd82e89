from __future__ import annotations

import math
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_behaviours.room.claims import claim_walls, crossings  # noqa: E402
from hfsm_sim.scenario import scenario_from_dict  # noqa: E402
from tools.room.experiments import QUICK, Config, trials  # noqa: E402
from tools.room.report import wilson, write  # noqa: E402
from tools.room.scenes import PAIR_GAP, REACH, room  # noqa: E402
from tools.room.trials import RoomLine, cleared_at, measure, phase, run_room_trial  # noqa: E402
from tools.sweep import run_sweep  # noqa: E402


@pytest.mark.parametrize("k", [2, 3, 4, 5])
def test_generated_rooms_are_valid_and_solvable(k: int) -> None:
    for n in range(2 * k, 2 * k + 4):
        for seed in (1, 2):
            data = room(seed, k, n, failure=True)
            scenario_from_dict(data)
            assert len(data["tables"]) == k and len(data["robots"]) == n
            size = data["room"]["width"], data["room"]["depth"]
            ways = claim_walls(data["tables"], *size, REACH)
            assert crossings(list(ways.values()), data["tables"], REACH) == 0
            robots = list(data["robots"].values())
            for i, t in enumerate(data["tables"]):  # robots 2i+1 and 2i+2 stand either side of table i
                for r in robots[2 * i: 2 * i + 2]:
                    assert math.hypot(r["x"] - t["x"], r["y"] - t["y"]) == pytest.approx(PAIR_GAP, abs=0.25)
            for a in range(n):
                for b in range(a + 1, n):
                    assert math.hypot(robots[a]["x"] - robots[b]["x"], robots[a]["y"] - robots[b]["y"]) > 0.8


def test_a_seed_always_draws_the_same_room_and_failure() -> None:
    assert room(7, 3, 8, failure=True) == room(7, 3, 8, failure=True)
    assert room(7, 3, 8) != room(8, 3, 8)
    failure = room(7, 3, 8, failure=True, fail_window=(10.0, 20.0))["failures"][0]
    assert failure["robot"] in room(7, 3, 8)["robots"] and 10.0 <= failure["at"] <= 20.0


def test_the_campaign_covers_the_issue() -> None:
    """At least 40 target rooms; K = 2..5 with N = 2K..2K+3, rooms with and without a failure;
    the `rate:` form; radio loss 0.1 and 0.3 on rooms that also run lossless."""
    every = trials(Config())
    target = [t for t in every if t.experiment == "target"]
    assert len(target) >= 40
    assert {len(t.scenario["tables"]) for t in target} == {3}
    assert {len(t.scenario["robots"]) for t in target} == {6, 7, 8}
    assert all(len(t.scenario["failures"]) == 1 for t in target)
    grid = [t for t in every if t.experiment == "kn"]
    kn = {(len(t.scenario["tables"]), len(t.scenario["robots"])) for t in grid}
    assert kn == {(k, n) for k in range(2, 6) for n in range(2 * k, 2 * k + 4)}
    for k, n in kn:
        rooms = [t for t in grid if (len(t.scenario["tables"]), len(t.scenario["robots"])) == (k, n)]
        assert sorted(len(t.scenario["failures"]) for t in rooms) == [0, 1]
    rated = [t for t in every if t.experiment == "rate"]
    assert rated and all("rate" in t.scenario["failures"][0] for t in rated)
    lossy = [t for t in every if t.experiment == "loss"]
    assert {t.radio_loss for t in lossy} == {0.1, 0.3}
    assert all(any(t.scenario == u.scenario and u.radio_loss == 0 for u in target) for t in lossy)


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


def test_the_report_goes_between_its_markers(tmp_path: Path) -> None:
    def result(trial: int, experiment: str, k: int, n: int, cleared: bool, **more: Any) -> dict[str, Any]:
        return {"trial": trial, "experiment": experiment, "x": n, "seed": trial, "k": k, "n": n, "loss": 0.0,
                "room": [8.0, 6.0], "cleared": cleared, "clear_time": 120.0 + trial if cleared else None,
                "time": 130.0 if cleared else 2100.0, "error": None if cleared else "stopped at --max-time",
                "distances": [0.01] * k if cleared else [0.01, 0.9, 0.02], "dropped": False, "collisions": 0,
                "carries": [], "wall": 40.0, "failures": [], **more}

    fail = {"robot": "r2", "at": 50.0, "phase": "mid-carry", "recovered": False}
    spare = {**fail, "phase": "spare", "recovered": True}
    results = [result(0, "target", 3, 6, True, failures=[spare]),
               result(1, "target", 3, 7, False, failures=[fail]), result(2, "kn", 2, 4, True),
               result(3, "kn", 3, 6, True), result(4, "kn", 3, 7, True),
               result(5, "rate", 3, 7, True, x=0.05, failures=[{**spare, "robot": "r4"}, spare]),
               result(6, "loss", 3, 6, True, seed=0, loss=0.3, failures=[spare])]
    doc = tmp_path / "ROOM.md"
    doc.write_text("# Room\n\nbefore\n<!-- room_bench:start -->\nold\n<!-- room_bench:end -->\nafter\n")
    write(results, doc, tmp_path / "fig", "tools/room_bench.py", 600.0, 2, "load average 1.00")
    text = doc.read_text(encoding="utf-8")
    assert text.startswith("# Room\n\nbefore\n<!-- room_bench:start -->") and text.endswith("end -->\nafter\n")
    assert "old" not in text
    assert "**Target rooms: 1 of 2 cleared (50 %; 95 % Wilson interval 9-91 %)** within 35 simulated minutes" in text
    assert "mid-carry: 0/1; spare: 4/4" in text
    assert "Failure rate 0.05 per robot per minute (3 tables, 7 robots): 1 of 1 cleared" in text
    assert "2 robots failed in all" in text
    assert "Radio loss, the same target rooms (seeds 0): 0 %: 1/1 cleared, median 120 s; 30 %: 1/1" in text
    assert "| 2 | 122 (1/1) |  |" in text and "| 3 | 123 (1/1) | 124 (1/1) |" in text  # without a failure
    assert "| 3 | 120 (1/1) | - (0/1) | 120 (1/2) |" in text  # with a failure: the target rooms
    assert "| 2 |  |  |  |" not in text
    assert "- trial 1 (target, seed 1): gaps 0.01, 0.90, 0.02 m" in text
    assert sorted(p.name for p in (tmp_path / "fig").iterdir()) == ["time_vs_k.png", "time_vs_n.png"]


@pytest.mark.slow
def test_results_are_the_same_on_one_and_two_workers() -> None:
    specs = [replace(t, max_time=8.0) for t in trials(QUICK)]
    one = run_sweep(run_room_trial, specs, workers=1)
    two = run_sweep(run_room_trial, specs, workers=2)
    assert [r["trial"] for r in one] == [0, 1]
    assert [{k: v for k, v in r.items() if k != "wall"} for r in one] == [
        {k: v for k, v in r.items() if k != "wall"} for r in two]
    assert [(r["k"], r["n"]) for r in one] == [(3, 6), (2, 4)]
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
