"""The bench's scenarios, as data for hfsm_sim/scenario.py: light robots on a grid in the left of the
room, targets on a grid in the right, as in the paper's Figure 2 (robots spread, tasks apart).

With 10 robots and 3 tasks it is `hfsm_sim/scenarios/alloc_3_tasks.yaml`; `density` packs the robots
closer (the ratio of areas of the paper's Figure 5), `speed` sets every robot's top speed
(Figure 7), `robots` grows the team and the room with it at the same density (Figure 6, 3 tasks
for every 10 robots).
"""

from __future__ import annotations

import math
from typing import Any

SPACING = 0.8  # metres between robots on the grid at density 1
ROW = 5  # robots a row
TASK_GAP = 3.6  # metres between targets: a robot passes between the rings of 1 m around them
TASK_ROWS = 5


def difficulties(k: int) -> list[float]:
    """k difficulties evenly spread in (0, 1): 0.3, 0.6, 0.9 for three tasks (the paper's)."""
    if k <= 3:
        return [0.3, 0.6, 0.9][:k] if k == 3 else [round(0.9 * (i + 1) / k, 3) for i in range(k)]
    return [round(0.1 + 0.8 * i / (k - 1), 3) for i in range(k)]


def scene(robots: int = 10, tasks: int = 3, *, density: float = 1.0, speed: float = 0.5,
          priorities: tuple[int, ...] | None = None, failures: list[dict[str, Any]] | None = None
          ) -> dict[str, Any]:
    """A scenario mapping: `robots` light robots, `tasks` targets (priorities in target order, by
    default 1..k), robots `SPACING / sqrt(density)` apart."""
    gap = SPACING / math.sqrt(density)
    rows = math.ceil(robots / ROW)
    task_cols = math.ceil(tasks / TASK_ROWS)
    task_rows = min(tasks, TASK_ROWS)
    width = 10.0 + TASK_GAP * (task_cols - 1)
    depth = max(8.0, TASK_GAP * task_rows + 1.0, SPACING * rows + 2.0)
    left = -width / 2 + 1.5
    placed = {}
    for i in range(robots):
        row, col = divmod(i, ROW)
        x = left + 1.5 + (col - (ROW - 1) / 2) * gap
        y = (row - (rows - 1) / 2) * gap
        placed[f"r{i + 1}"] = {"x": round(x, 3), "y": round(y, 3), "yaw": 0, "body": "light", "speed": speed}
    order = priorities or tuple(range(1, tasks + 1))
    targets = []
    for i, (d, prio) in enumerate(zip(difficulties(tasks), order, strict=True)):
        col, row = divmod(i, TASK_ROWS)
        x = width / 2 - 1.75 - TASK_GAP * col
        y = (row - (task_rows - 1) / 2) * TASK_GAP
        targets.append({"id": f"t{i + 1}", "x": round(x, 3), "y": round(y, 3), "difficulty": d,
                        "priority": prio})
    return {
        "description": f"tararc bench: {robots} robots, {tasks} targets, density {density}, speed {speed}",
        "room": {"width": width, "depth": depth},
        "tables": [],
        "targets": targets,
        "robots": placed,
        "jitter": {"position": 0.05, "yaw": 5},
        "failures": failures or [],
    }
