"""The whole task over a bad radio: the handshakes are said again until answered at a barrier."""

from __future__ import annotations

from pathlib import Path

import pytest

from hfsm_behaviours.trial import TrialSpec, run_trial

ROOT = Path(__file__).resolve().parents[2]
MACHINE = str(ROOT / "machines" / "move_furniture.yaml")


@pytest.mark.slow
@pytest.mark.parametrize(("loss", "latency"), [(0.3, 0.1), (0.0, 2.0)], ids=["loss-30%", "latency-2s"])
def test_move_furniture_survives_the_radio(loss: float, latency: float) -> None:
    result = run_trial(TrialSpec(MACHINE, "opposite_long_side", 0, radio_loss=loss, radio_latency=latency))
    assert result.error is None
    assert result.outcomes == {"r1": "at_wall", "r2": "at_wall"}
    score = result.score
    assert score["success"] and not score["dropped"] and score["robot_collisions"] == 0, score
