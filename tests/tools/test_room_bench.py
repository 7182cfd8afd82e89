"""tools/room_bench.py: generated rooms, the campaign's trials, the report (the runs themselves are
the slow room tests' business: tests/behaviours/test_clear_room.py)."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from behaviours.room.claims import claim_walls, overlap  # noqa: E402
from behaviours.room.plan import tables_of  # noqa: E402
from sim.scenario import scenario_from_dict  # noqa: E402
from tools.room.report import summary_lines, table_lines  # noqa: E402
from tools.room.scenes import pairs_apart, room  # noqa: E402
from tools.room_bench import QUICK, campaign, write_docs  # noqa: E402


@pytest.mark.parametrize(("k", "n"), [(2, 4), (2, 7), (3, 6), (3, 9), (4, 8), (5, 13)])
def test_every_room_is_a_valid_scenario_whose_claimed_ways_do_not_cross(k: int, n: int) -> None:
    for seed in range(3):
        scenario = room(k, n, seed, "early")
        checked = scenario_from_dict(scenario)
        assert len(checked.all_tables) == k and len(checked.robots) == n
        assert pairs_apart(scenario) >= 0.99, "robots start apart"
        ways = claim_walls(tables_of(checked.tasks()), scenario["room"]["width"], scenario["room"]["depth"])
        corridors = [w.corridor for w in ways.values()]
        assert not any(overlap(a, b) for i, a in enumerate(corridors) for b in corridors[i + 1:])
        assert scenario["failures"][0]["robot"] in {f"r{i + 1}" for i in range(2 * k)}


def test_a_seed_gives_the_same_room() -> None:
    assert room(3, 8, 4, "mid") == room(3, 8, 4, "mid")
    assert room(3, 8, 4) != room(3, 8, 5)
    with pytest.raises(ValueError, match="2K <= N"):
        room(3, 10, 0)


def test_the_campaign_covers_failures_and_loss() -> None:
    trials = campaign(2)
    assert {t.failure for t in trials} == {"none", "early", "mid"}
    assert any(t.loss == 0.3 for t in trials) and len(QUICK) == 2


def _result(k: int, n: int, failure: str, cleared: bool, time: float) -> dict[str, Any]:
    return {"k": k, "n": n, "seed": 0, "failure": failure, "loss": 0.0, "cleared": cleared, "time": time,
            "collisions": 0, "wall": 60.0, "failed": [], "error": None}


def test_the_report_counts_rooms_cleared(tmp_path: Path) -> None:
    results = [_result(2, 4, "none", True, 120.0), _result(2, 4, "none", True, 130.0),
               _result(3, 8, "mid", False, 2100.0)]
    assert table_lines(results)[2] == "| 2 | 4 | none | 0 | 2/2 | 125 | 130 | 0 | 60 |"
    assert "- one robot failing in the carry (50-90 s): 0 of 1 rooms cleared within 35 simulated minutes." \
        in summary_lines(results)
    doc = tmp_path / "ROOM.md"
    write_docs({"command": "tools/room_bench.py", "wall": 60.0, "workers": 2, "results": results}, doc,
               tmp_path / "figures")
    assert "<!-- room_bench:start -->" in doc.read_text(encoding="utf-8")
    assert (tmp_path / "figures" / "time.png").is_file() and (tmp_path / "figures" / "cleared.png").is_file()
