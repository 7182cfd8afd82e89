"""The contact census (tools/room/contacts.py): what each robot runs, read off the trace, and the
kinds a contact is classified by; a short room run for real, its contacts recorded as the scorer
counts them."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.room.contacts import Doing, census, classify  # noqa: E402


def record(t: float, agent: str, kind: str, path: list[str], do: str | None = None) -> dict[str, object]:
    return {"t": t, "agent": agent, "kind": kind, "path": path, **({"do": do} if do else {})}


def test_what_a_robot_runs_is_its_entered_states_deepest_first() -> None:
    doing = Doing()
    doing.write(record(0.0, "r1", "enter", ["clear_room", "work"]))
    doing.write(record(0.0, "r1", "enter", ["clear_room", "work", "carry"], "room_carry"))
    doing.write(record(1.0, "r1", "enter", ["clear_room", "work", "carry", "walk"], "go_along"))
    assert doing.of("r1") == ["go_along", "room_carry", "work"]
    doing.write(record(2.0, "r1", "exit", ["clear_room", "work", "carry"]))
    assert doing.of("r1") == ["work"] and doing.now == 2.0
    doing.write(record(3.0, "r2", "failed", []))
    assert doing.failed == {"r2": 3.0}


def test_contacts_are_classified_by_the_deepest_behaviour_of_a_known_kind() -> None:
    assert classify(["small_step_sideways", "step_together", "move_table"], False) == "carrying"
    assert classify(["wait_for", "hear", "elect_leader"], False) == "waiting"
    assert classify(["walk_randomly", "look_for_table"], False) == "approach round the table"
    assert classify(["go_along", "room_carry"], False) == "walking"
    assert classify(["back_away"], False) == "stepping back"
    assert classify(["go_along"], True) == "failed"
    assert classify(["something_new"], False) == "other:something_new"
    # a walker's heartbeat runs deeper than its walk (generated room mixed-34001's r1): walking
    assert classify(["wait", "say", "wait", "wait", "go_along", "room_carry"], False) == "walking"


@pytest.mark.slow
def test_a_room_is_run_and_its_contacts_listed() -> None:
    room = census("open", 3, 5.0)
    assert room["stratum"] == "open" and room["seed"] == 3 and room["sim"] == 5.0
    assert room["contacts"] == [] and room["collisions"] == 0
