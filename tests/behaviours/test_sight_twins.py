"""Colours repeat beyond ten robots: looking for the leader by its colour and its table
(`hfsm_behaviours.approach.sight.scan_for_robot`), a robot of that colour far from the table seen first
is passed over for one near it; judged without a world (the views are given)."""

from __future__ import annotations

from typing import Any

import pytest

from hfsm_behaviours.approach import sight
from hfsm_behaviours.approach.sight import NO_ROBOT, RobotSighting, scan_for_robot

TABLE = (2.0, 0.0)
LEADER = RobotSighting(True, (2.0, 0.6), 0.3, 2.1)
TWIN = RobotSighting(True, (1.0, -3.0), -1.2, 3.2)  # wears the leader's colour, at another table


def views(monkeypatch: pytest.MonkeyPatch, by_yaw: dict[float, RobotSighting]) -> list[float]:
    looked: list[float] = []

    def see(body: Any, yaw: float, pitch: float, own: int, only: int = -1, near: Any = None) -> RobotSighting:
        looked.append(yaw)
        return by_yaw.get(yaw, NO_ROBOT)

    monkeypatch.setattr(sight, "see_robot", see)
    return looked


def test_a_twin_seen_first_is_passed_over_for_the_leader_at_its_table(monkeypatch: pytest.MonkeyPatch) -> None:
    looked = views(monkeypatch, {0.0: TWIN, 0.9: LEADER})
    assert scan_for_robot(None, [0.0, 0.9, -0.9], 0.3, own=4, only=1, near=TABLE) == LEADER  # type: ignore[arg-type]
    assert looked == [0.0, 0.9]  # the leader near its table ends the scan


def test_a_robot_of_the_colour_far_from_the_table_is_taken_when_no_other_is_seen(
        monkeypatch: pytest.MonkeyPatch) -> None:
    looked = views(monkeypatch, {0.9: TWIN})
    assert scan_for_robot(None, [0.0, 0.9, -0.9], 0.3, own=4, only=1, near=TABLE) == TWIN  # type: ignore[arg-type]
    assert looked == [0.0, 0.9, -0.9]


def test_without_a_table_the_first_robot_seen_is_taken(monkeypatch: pytest.MonkeyPatch) -> None:
    looked = views(monkeypatch, {0.0: TWIN, 0.9: LEADER})
    assert scan_for_robot(None, [0.0, 0.9], 0.3, own=4, only=1) == TWIN  # type: ignore[arg-type]
    assert looked == [0.0]
