from __future__ import annotations

import math
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_sim.scenario import scenario_from_dict  # noqa: E402
from tools.sweep import Shard, SweepError, run_sweep  # noqa: E402
from tools.tararc.experiments import Config, help_trials, main_trials  # noqa: E402
from tools.tararc.measure import Timeline, measure  # noqa: E402
from tools.tararc.report import growth, median, timed, write  # noqa: E402
from tools.tararc.scenes import scene  # noqa: E402
from tools.tararc.trials import BenchTrial, run_bench_trial  # noqa: E402


def _exit(t: float, agent: str, state: str) -> dict[str, Any]:
    return {"t": t, "agent": agent, "path": ["tararc", "work", "task", state], "kind": "exit"}


def test_every_generated_scenario_is_valid() -> None:
    for trial in main_trials(Config()):
        scenario_from_dict(trial.scenario)
    assert len(scene(robots=50, tasks=15)["robots"]) == 50


def test_density_packs_the_robots_closer() -> None:
    def spread(density: float) -> float:
        xs = [r["x"] for r in scene(density=density)["robots"].values()]
        return max(xs) - min(xs)

    assert spread(4.0) == pytest.approx(spread(1.0) / 2, abs=0.01)


def test_priorities_follow_the_order_given() -> None:
    targets = scene(priorities=(3, 1, 2))["targets"]
    assert [(t["difficulty"], t["priority"]) for t in targets] == [(0.3, 3), (0.6, 1), (0.9, 2)]


def test_the_timeline_gives_grouped_enclosed_and_recovery() -> None:
    line = Timeline()
    records = [
        _exit(2.0, "a", "form_up"), _exit(5.0, "b", "form_up"), _exit(5.0, "a", "meet_formed"),
        _exit(5.0, "b", "meet_formed"), {"t": 8.0, "agent": "c", "path": ["tararc"], "kind": "failed"},
        _exit(9.0, "a", "assign"), _exit(9.5, "b", "assign"), _exit(20.0, "a", "there"),
        _exit(21.0, "b", "there"), _exit(21.0, "b", "meet_enclosed"),
        {"t": 21.0, "agent": "b", "path": ["tararc", "remember"], "kind": "event", "vars": {"outcomes": [True]}},
        {"t": 21.0, "agent": "a", "path": ["tararc", "remember"], "kind": "event", "vars": {"outcomes": [True]}},
        {"t": 1.0, "agent": "a", "path": ["tararc", "x"], "kind": "receive"},
    ]  # fmt: skip
    for record in records:
        line.write(record)
    got = measure(line, ["a", "b", "c"], None)
    assert got == {"completed": True, "grouped": 5.0, "enclosed": 21.0, "converge": 16.0,
                   "failed": {"c": 8.0}, "recovery": 1.5}
    assert measure(line, ["a", "b", "c"], "stopped")["converge"] == math.inf


def test_help_trials_fail_each_robot_mid_move() -> None:
    base = [{"experiment": "table1", "x": [1, 2, 3], "seed": 1, "grouped": 20.0, "enclosed": 50.0}]
    trials = help_trials(Config(help_seeds=1), base)
    assert [t.x for t in trials] == [f"r{i}" for i in range(1, 11)]
    assert {f["at"] for t in trials for f in t.scenario["failures"]} == {29.0}


def test_report_helpers() -> None:
    assert median([3.0, math.inf, 1.0]) == 2.0
    assert median([math.inf]) == math.inf
    assert "5.0 times as many" in growth([(10, 2.0), (50, 10.0)])


@pytest.mark.slow
def test_results_are_the_same_on_one_and_two_workers() -> None:
    trials = [BenchTrial("tiny", s, s, scene(robots=4, tasks=2), max_time=15.0) for s in (1, 2)]
    one = run_sweep(run_bench_trial, trials, workers=1)
    two = run_sweep(run_bench_trial, trials, workers=2)
    assert [r["trial"] for r in one] == [0, 1]
    assert [{k: v for k, v in r.items() if k != "wall"} for r in one] == [
        {k: v for k, v in r.items() if k != "wall"} for r in two]
    assert all(r["collisions"] == 0 for r in one)


def test_the_report_from_results(tmp_path: Path) -> None:
    def run(exp: str, x: Any, done: bool = True, **more: Any) -> dict[str, Any]:
        return {"experiment": exp, "x": x, "seed": 1, "completed": done, "grouped": 10.0 * (1 + (x == 20)),
                "enclosed": 40.0 if done else math.inf, "converge": 30.0 if done else math.inf,
                "collisions": 0, "groups": [{"agent": "r1", "members": ["r1"], "B": 3.0, "F": 0.5, "difficulty": 0.3}],
                **more}

    results = [run("table1", [1, 2, 3]), run("table1", [3, 2, 1], done=False), run("density", 1.0),
               run("size", 10), run("size", 20), run("speed", 0.5),
               {"experiment": "ability", "x": 0, "seed": 1, "runs": [run("ability", 0), run("ability", 0)]},
               run("help", "r1", agents=["r1"], recovery=5.0), run("help", "r2", agents=["r1"], recovery=6.0)]
    doc = tmp_path / "TARARC.md"
    lines = write(results, doc, tmp_path / "figures", "tools/tararc_bench.py", 90.0, len(results))
    text = doc.read_text(encoding="utf-8")
    assert "| (3, 2, 1) | ∞ | ∞ | 0/1 | 0 |" in text and "| (1, 2, 3) | 33.05 | 30.0 | 1/1 | 0 |" in text
    assert "- Priority orders that never finish: 1 of 2 (paper: 1 of 6): [3, 2, 1]." in lines
    assert "(2.0 times as many) the time to group goes from 10.0 s to 20.0 s (2.00 times)" in text
    assert "| agent | 1 | 1/1 | 5.0 |" in text and "| member | 1 | 1/1 | 6.0 |" in text
    assert sorted(p.name for p in (tmp_path / "figures").iterdir()) == [
        "fig5_density.png", "fig6_size.png", "fig7_speed.png", "fig8_ability.png"]


@pytest.mark.slow
def test_shards_merged_give_the_results_of_one_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import tools.tararc_bench as bench

    tiny = [BenchTrial("tiny", s, s, scene(robots=4, tasks=2), max_time=15.0) for s in (1, 2, 3)]
    monkeypatch.setattr(bench, "main_trials", lambda _config: tiny)
    config = Config(help_seeds=0)
    whole = bench.first_stage(config, workers=1)
    for i in (1, 2):
        assert bench.first_stage(config, workers=1, shard=Shard(i, 2), shards=tmp_path) is None
    merged = bench.first_stage(config, shards=tmp_path, merge=True)
    assert whole is not None and merged is not None

    def timeless(results: list[dict[str, Any]]) -> list[dict[str, Any]]:
        return [{k: v for k, v in r.items() if k != "wall"} for r in results]

    assert timeless(merged) == timeless(whole) and [r["trial"] for r in merged] == [0, 1, 2]
    assert timeless(bench.run_bench(config, workers=1, first=merged)) == timeless(whole)
    with pytest.raises(SweepError, match="no shards"):
        bench.first_stage(config, shards=tmp_path / "none", merge=True)


def test_the_time_to_group_counts_runs_that_grouped_but_missed_a_task() -> None:
    rs = [{"completed": False, "grouped": 20.0, "converge": math.inf},
          {"completed": True, "grouped": 10.0, "converge": 5.0},
          {"completed": False, "grouped": math.inf, "converge": math.inf}]
    assert timed(rs, "grouped") == [20.0, 10.0]
    assert timed(rs, "converge") == [5.0]


@pytest.mark.slow
def test_only_figure_8_runs_again_and_its_group_failure_shows(tmp_path: Path) -> None:
    import json

    import tools.tararc_bench as bench

    raw = tmp_path / "tararc.json"
    kept = {"experiment": "table1", "x": [1, 2, 3], "seed": 1, "trial": 0, "completed": True, "grouped": 8.0,
            "enclosed": 20.0, "converge": 12.0, "collisions": 0, "wall": 1.0}
    raw.write_text(json.dumps({"command": "tools/tararc_bench.py", "wall": 60.0, "workers": 2,
                               "results": [kept]}), encoding="utf-8")
    doc, figures = tmp_path / "TARARC.md", tmp_path / "figures"
    args = ["--quick", "--only", "ability", "--workers", "1", "--raw", str(raw), "--doc", str(doc),
            "--figures", str(figures), "--perf", str(tmp_path / "PERF.md")]
    assert bench.main(args) == 0
    saved = json.loads(raw.read_text(encoding="utf-8"))
    assert [r["experiment"] for r in saved["results"]] == ["table1", "ability"]
    runs = saved["results"][1]["runs"]
    assert [run["completed"] for run in runs] == [True, True, False, True]
    middle = next(g for g in runs[2]["groups"] if g["difficulty"] == 0.6)
    assert sorted(runs[2]["failed"]) == sorted(middle["members"])  # the group of the second hardest, wholly
    text = doc.read_text(encoding="utf-8")
    assert "task 0.6 → 0.3 (the easiest)" in text and "Rerun since: `tools/tararc_bench.py --quick --only" in text
    assert not (tmp_path / "PERF.md").exists()
    assert bench.main([*args[:2], "help", *args[3:]]) == 2
