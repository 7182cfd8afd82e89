"""Rooms of K tables and N humanoids for the campaign, as scenario mappings (sim/scenario.py).

Tables stand in a row 4 m apart across the middle of the room: the first along x (carried to the
west wall), the last along x (east wall), those between across it (north or south wall, as the
claims decide). Each table's pair starts on its two long sides facing it, 1.2 m out, as in
`room_3_tables`; the N - 2K spares stand 1 m apart along the south wall, about the middle. A seed varies the
tables' sizes and places a little (`rng`), and may fail one robot: `early` (on its way to its
table, 5-25 s) or `mid` (in the carry, 50-90 s).
"""

from __future__ import annotations

import math
import random
from typing import Any

GAP = 4.0  # metres between table centres
DEPTH = 6.0


def _pair(x: float, y: float, yaw: float) -> list[dict[str, Any]]:
    if yaw == 0:
        return [{"x": x + 0.2, "y": y - 1.2, "yaw": 90}, {"x": x - 0.2, "y": y + 1.2, "yaw": -90}]
    return [{"x": x - 1.2, "y": y - 0.2, "yaw": 0}, {"x": x + 1.2, "y": y + 0.2, "yaw": 180}]


def room(k: int, n: int, seed: int, failure: str = "none") -> dict[str, Any]:
    """A scenario mapping: k tables (2..5), n robots (2k..2k+3), maybe one failure."""
    if not 2 <= k <= 5 or not 2 * k <= n <= 2 * k + 3:
        raise ValueError(f"need 2 <= K <= 5 and 2K <= N <= 2K + 3, got K={k}, N={n}")
    rng = random.Random(f"room-{k}-{n}-{seed}")
    width = GAP * (k - 1) + 5.0
    tables, robots = [], []
    for i in range(k):
        yaw = 0.0 if i in (0, k - 1) else 90.0
        x = round(-GAP * (k - 1) / 2 + GAP * i + rng.uniform(-0.15, 0.15), 2)
        y = round(rng.uniform(-0.3, 0.3), 2) if yaw == 0 else round(rng.uniform(-0.6, 0.6), 2)
        length = round(rng.uniform(0.7, 1.0), 2)
        width_t = round(min(length - 0.1, rng.uniform(0.45, 0.55)), 2)
        tables.append({"id": f"table{i + 1}", "x": x, "y": y, "yaw": yaw, "length": length, "width": width_t,
                       "priority": i + 1})
        robots += _pair(x, y, yaw)
    spares = n - 2 * k
    for j in range(spares):
        robots.append({"x": round((j - (spares - 1) / 2) * 1.0, 2), "y": -DEPTH / 2 + 0.7, "yaw": 90})
    scenario: dict[str, Any] = {
        "description": f"room bench: {k} tables, {n} humanoids, seed {seed}, failure {failure}",
        "task": "table_to_wall",
        "room": {"width": width, "depth": DEPTH},
        "tables": tables,
        "robots": {f"r{i + 1}": {**r, "body": "full"} for i, r in enumerate(robots)},
        "jitter": {"position": 0.1, "yaw": 10},
    }
    if failure != "none":
        low, high = {"early": (2.0, 12.0), "mid": (50.0, 90.0)}[failure]
        who = f"r{rng.randrange(2 * k) + 1}"  # a robot of a pair: a spare failing changes nothing
        scenario["failures"] = [{"robot": who, "at": round(rng.uniform(low, high), 1)}]
    return scenario


def pairs_apart(scenario: dict[str, Any]) -> float:
    """The smallest distance between two robots' starts (a layout check for tests)."""
    points = [(r["x"], r["y"]) for r in scenario["robots"].values()]
    return min(math.dist(a, b) for i, a in enumerate(points) for b in points[i + 1:])
