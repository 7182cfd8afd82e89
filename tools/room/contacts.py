"""A contact census of one generated room (tools/room_contacts.py): every robot-robot contact episode
the scorer counts, with its time and what each robot was running then, read off the trace."""

from __future__ import annotations

import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from hfsm_behaviours.trial import TrialSpec, run_trial
from hfsm_sim.roomgen import draw
from hfsm_sim.scorer import Scorer

MACHINE = Path(__file__).resolve().parents[2] / "machines" / "clear_room.yaml"

# What a robot does, by the behaviours it runs (deepest first wins): the kinds.
KINDS: tuple[tuple[str, frozenset[str]], ...] = (
    ("carrying", frozenset({"small_step_sideways", "step_together", "drag_table", "move_table"})),
    ("lifting", frozenset({"lift_table", "synchronised_lift_table", "land_table", "call_off"})),
    ("stepping back", frozenset({"back_away"})),
    ("approach round the table", frozenset({
        "go_to_opposite_side_of_table", "go_to_the_lifting_point", "recentre_to_middle_of_table",
        "align_to_middle_of_table", "position_to_centre_of_table_side", "align_body_parallel",
        "go_to_table", "centre_table", "look_for_table", "scan_for_table", "look_for_leader",
        "wait_until_leader_at_centre_of_table", "walk_sideways", "walk_randomly", "spin_on_the_spot",
        "look_left_and_right", "choose_carry_direction", "table_at_wall"})),
    ("walking", frozenset({"go_along", "go_to", "room_route", "room_give_way"})),
    ("waiting", frozenset({"hold", "wait", "barrier", "handshake", "hear", "room_team", "room_alive"})),
)


@dataclass
class Doing:
    """A trace sink keeping each robot's running states (path -> its `do`), and when it failed."""

    running: dict[str, dict[tuple[str, ...], str]] = field(default_factory=dict)
    failed: dict[str, float] = field(default_factory=dict)
    now: float = 0.0

    def write(self, record: dict[str, Any]) -> None:
        self.now = max(self.now, float(record["t"]))
        agent, kind, path = record["agent"], record["kind"], tuple(record["path"])
        if kind == "failed":
            self.failed.setdefault(agent, record["t"])
        elif kind == "enter":
            self.running.setdefault(agent, {})[path] = str(record.get("do") or path[-1] if path else "")
        elif kind == "exit":
            states = self.running.get(agent, {})
            for p in [p for p in states if p[:len(path)] == path]:
                del states[p]

    def of(self, agent: str) -> list[str]:
        """The behaviours the robot runs, deepest first."""
        states = self.running.get(agent, {})
        return [states[p] for p in sorted(states, key=len, reverse=True)]

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


def classify(doing: list[str], failed: bool) -> str:
    """The first kind (in KINDS' order: carrying before walking before waiting) of any behaviour the
    robot runs: a walker's background regions (its heartbeat's `say`, `wait`) run deeper than its
    walk, so depth alone would call it waiting."""
    if failed:
        return "failed"
    for kind, names in KINDS:
        if any(name in names for name in doing):
            return kind
    return "other:" + (doing[0] if doing else "-")


def census(stratum: str, seed: int, max_time: float) -> dict[str, Any]:
    """Run the room (stratum, seed) once and list its robot-robot contacts."""
    scenario = draw(seed, stratum)
    doing = Doing()
    contacts: list[dict[str, Any]] = []
    observe = Scorer.observe

    def watched(self: Scorer) -> None:
        before = self._touching
        observe(self)
        for kind, a, b in sorted(self._touching - before):
            if kind == "robot":
                contacts.append({"t": round(doing.now, 2), "a": a, "b": b,
                                 "a_doing": doing.of(a)[:12], "b_doing": doing.of(b)[:12],
                                 "a_failed": a in doing.failed, "b_failed": b in doing.failed})

    Scorer.observe = watched  # type: ignore[method-assign]
    started = time.perf_counter()
    try:
        with tempfile.TemporaryDirectory(prefix="room-contacts-") as tmp:
            path = Path(tmp) / f"{stratum}-{seed}.yaml"
            path.write_text(yaml.safe_dump(scenario, sort_keys=False), encoding="utf-8")
            result = run_trial(TrialSpec(str(MACHINE), str(path), seed, {}, max_time), doing)
    finally:
        Scorer.observe = observe  # type: ignore[method-assign]
    return {"stratum": stratum, "seed": seed, "success": bool(result.score["success"]),
            "distances": result.score.get("table_wall_distances") or [result.score["table_wall_distance"]],
            "collisions": result.score["robot_collisions"], "contacts": contacts,
            "sim": round(result.time, 2), "error": result.error, "outcomes": result.outcomes,
            "wall": round(time.perf_counter() - started, 1)}
