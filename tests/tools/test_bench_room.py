"""tools/bench_room.py and tools/room_profile.py: rooms picked by their robots, the table's medians and
trace comparison, one real run timed, and a profile's parts summed by name."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from hfsm_sim import roomgen  # noqa: E402
from tools.bench_room import pick_room, report, run_once  # noqa: E402
from tools.room_profile import REST, ROWS, row_seconds  # noqa: E402


@pytest.mark.parametrize("robots", [4, 8])
def test_a_room_is_picked_with_that_many_robots(robots: int) -> None:
    stratum, seed, scenario = pick_room(robots)
    assert len(scenario["robots"]) == robots and scenario == roomgen.draw(seed, stratum)


def _run(wall: float, cpu: float, sha: str) -> dict[str, float | str]:
    return {"wall": wall, "cpu": cpu, "simulated": 10.0, "sha": sha}


def test_the_table_gives_medians_per_simulated_second_and_whether_the_traces_match() -> None:
    data = {"rev": "main", "short": "abc1234", "now": None, "seconds": 10.0, "rounds": 3,
            "rooms": {4: ("open", 1), 8: ("close", 2)},
            "rows": {4: {"before": [_run(20, 2, "a"), _run(30, 4, "b"), _run(10, 3, "c")],
                         "now": [_run(10, 1, "a"), _run(15, 2, "b"), _run(5, 3, "c")]},
                     8: {"before": [_run(20, 2, "a")], "now": [_run(10, 1, "z")]}}}
    lines = report(data, 60.0)
    row4 = next(line for line in lines if line.startswith("| 4 |"))
    row8 = next(line for line in lines if line.startswith("| 8 |"))
    assert row4 == "| 4 | `open-1` | 2.000 | 0.300 | 1.000 | 0.200 | 0.67x | yes |"
    assert row8.endswith("| 0.50x | no |")


@pytest.mark.slow
def test_one_room_run_is_timed_and_its_trace_hashed(tmp_path: Path) -> None:
    stratum, seed, scenario = pick_room(4)
    path = tmp_path / f"{stratum}-{seed}.yaml"
    roomgen.write(path, scenario)
    runs = [run_once(ROOT, path, 1.0, tmp_path / f"{i}.jsonl") for i in range(2)]
    assert all(run["simulated"] == 1.0 and run["cpu"] > 0 and run["wall"] > 0 for run in runs)
    assert runs[0]["sha"] == runs[1]["sha"]  # seeded: the same trace
    assert not list(tmp_path.glob("*.jsonl"))


def test_a_profile_row_sums_its_functions_by_file_and_name() -> None:
    times = {("/x/hfsm_sim/world.py", "advance"): (1.0, 5.0), ("/y/hfsm_behaviours/simworld.py", "advance"):
             (1.0, 6.0), ("~", "<built-in method pybullet.stepSimulation>"): (2.0, 2.0)}
    label, parts, kind, _ = ROWS[0]
    assert "world advance" in label and row_seconds(times, parts, kind) == 5.0
    assert row_seconds(times, ROWS[1][1], ROWS[1][2]) == 2.0
    assert REST.startswith("the rest")
