"""Ground-truth scoring: contacts watched every physics step, table and robots at the end."""

from __future__ import annotations

import math
from typing import Any

import pybullet as p

from hfsm_sim.truth import Truth

TOUCH = 0.001
FALLEN = math.radians(45.0)
TIPPED = math.radians(30.0)


class Scorer:
    """Counts contact episodes (a run of consecutive physics steps with contact)."""

    def __init__(self, cid: int, truth: Truth, success_distance: float = 0.15) -> None:
        self._cid = cid
        self._truth = truth
        self.success_distance = success_distance
        self._names = list(truth.robot_ids)
        self._tables = {t.body for t in truth.tables}
        self._ids = {truth.robot_id(n): n for n in self._names}
        self._kinds: dict[int, str] = dict.fromkeys(truth.room_bodies.walls, "wall")
        self._kinds.update(dict.fromkeys(self._tables, "table"))
        self._kinds.update(dict.fromkeys(self._ids, "robot"))
        self._touching: set[tuple[str, str, str]] = set()
        self.episodes: dict[str, int] = {"robot": 0, "table": 0, "wall": 0}
        self.bumps: dict[str, bool] = dict.fromkeys(self._names, False)
        self.dropped = False
        self.fallen: set[str] = set()

    def observe(self) -> None:
        """Call after every physics step: one query of all the world's contacts (each pair once)."""
        now: set[tuple[str, str, str]] = set()
        ids, kinds, bumps = self._ids, self._kinds, self.bumps
        # most contacts are no robot's (a table's legs on the floor) or not touching (a body's base
        # hovering over the floor): passed over in one comprehension
        touching = [(c[1], c[2]) for c in p.getContactPoints(physicsClientId=self._cid)
                    if not c[8] > TOUCH and (c[1] in ids or c[2] in ids)]
        for a, b in touching:
            for me, other in ((a, b), (b, a)):
                name = ids.get(me)
                if name is None:
                    continue
                kind = kinds.get(other)
                if kind is not None:
                    bumps[name] = True
                    partner = ids.get(other, "")
                    now.add((kind, min(name, partner), max(name, partner)) if partner
                            else (kind, name, ""))
        before = self._touching
        if now != before:
            for key in now - before:
                self.episodes[key[0]] += 1
            self._touching = now

    def take_bumps(self) -> dict[str, bool]:
        bumps, self.bumps = self.bumps, dict.fromkeys(self._names, False)
        return bumps

    def check_poses(self) -> None:
        """Call once per control tick: records a tipped table and fallen robots."""
        if any(self._truth.table_tilt(i) > TIPPED for i in range(len(self._truth.tables))):
            self.dropped = True
        for name in self._names:
            if self._truth.robot_tilt(name) > FALLEN:
                self.fallen.add(name)

    def score(self, time: float, *, dropped: bool = False) -> dict[str, Any]:
        """The outcome so far; `dropped` adds what the lifting rules saw to the scorer's own view.

        Success: every table within `success_distance` of a wall, none dropped, no robot-robot
        collision. `table_wall_distance` is the farthest table's gap (None in a room without
        tables); `table_wall_distances` lists each table's, in scenario order, when there are
        several or none."""
        distances = [round(self._truth.table_wall_distance(i), 4) for i in range(len(self._truth.tables))]
        distance = max(distances) if distances else None
        robot_hits = self.episodes["robot"]
        dropped = dropped or self.dropped
        success = all(d <= self.success_distance for d in distances) and not dropped and robot_hits == 0
        score: dict[str, Any] = {
            "success": bool(success),
            "table_wall_distance": distance,
            "dropped": dropped,
            "robot_collisions": robot_hits,
            "robot_table_collisions": self.episodes["table"],
            "robot_wall_collisions": self.episodes["wall"],
            "robots_fallen": sorted(self.fallen),
            "time": round(time, 4),
        }
        if len(distances) != 1:
            score["table_wall_distances"] = distances
        return score
