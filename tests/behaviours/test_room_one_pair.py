"""Clear the room, first brick (issue 10): in a room of two tables, one pair carries the table it
faces to a wall, and the other table stays where it is."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from room_run import run_room

from hfsm.cli.run import main

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.slow
def test_one_pair_carries_one_table_of_two(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    argv = [str(ROOT / "machines" / "move_furniture.yaml"), "--scenario", "room_one_pair", "--seed", "0"]
    code = main([*argv, "--json", "--no-video", "--out", str(tmp_path), "--quiet"])
    out, err = capsys.readouterr()
    result = json.loads(out)
    assert code == 0, err
    assert {a: r["outcome"] for a, r in result["agents"].items()} == {"r1": "at_wall", "r2": "at_wall"}
    score = result["score"]
    table1, table2 = score["table_wall_distances"]
    assert table1 <= 0.15, "the pair's table is at a wall"
    assert table2 == pytest.approx(1.5, abs=0.01), "the other table has not moved off its start"
    assert not score["dropped"] and score["robot_collisions"] == 0


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 1])
def test_a_pair_told_its_table_carries_it_and_leaves_the_other(seed: int) -> None:
    """Each robot is told where table1 stands (move_furniture's `table`, own start frame); seed 1
    is a run where, told nothing, the leader squares up on a rectangle of both tables and fails."""
    room = run_room("room_one_pair", seed, {"r1": "table1", "r2": "table1"})
    assert room.outcomes == {"r1": "at_wall", "r2": "at_wall"}
    assert sorted(room.roles.values()) == ["assistant", "leader"]
    assert room.score["table_wall_distances"][0] <= 0.15
    assert room.moved["table2"] < 0.01, "the other table stays where it is"
    assert not room.score["dropped"] and room.score["robot_collisions"] == 0
