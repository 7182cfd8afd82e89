"""The assistant's walk round its table in the simulator (go_to_opposite_side_of_table), a robot standing
on the corner its blind route walks to (`data/around/corner.yaml`): in a room (its table named) it
reads its range finder, goes round the table's other end past its leader and arrives with no
contact; blind (the paper's primitive, no table named) the same walk touches that robot."""

from __future__ import annotations

from pathlib import Path

import pytest
from helpers import sim_json

DATA = Path(__file__).parent / "data" / "around"


@pytest.mark.slow
def test_the_walk_round_takes_the_free_way_and_touches_nobody(capsys: pytest.CaptureFixture[str]) -> None:
    result = sim_json(capsys, DATA / "round.yaml", DATA / "corner.yaml", (), max_time=300)
    assert result["score"]["robot_collisions"] == 0
    assert result["agents"]["r2"]["outcome"] == "arrived"


@pytest.mark.slow
def test_blind_the_same_walk_touches(capsys: pytest.CaptureFixture[str]) -> None:
    result = sim_json(capsys, DATA / "round.yaml", DATA / "corner.yaml", ("table=[]",), max_time=300)
    assert result["score"]["robot_collisions"] > 0
