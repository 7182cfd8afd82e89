"""Where a waiting robot stands out of the way of the carrying pairs.

A spare, or a robot idle after its table, waits where it happens to be (clear_room's `wait`). Standing
in a table's claimed carry corridor it blocks that table: the pair's steps are held (the table's
legs, below the waiting robot's range finder when the table is landed, push into it), and a leader
whose steps are held at once takes the block for the wall (generated room walls-34001: the spare r5,
waiting where it started, stopped table1 1.2 m short of its wall, and the pair said it was there).
So it first steps to the nearest point out of every corridor of a table not yet done. Nor does it
wait beside another table still to be carried (within `NEAR` m of its top), where that table's pair
stands, walks round and steps in blind (held-out room narrow-38000: a leader waiting its turn beside
the table another pair carried first was walked into three times by that pair's assistant).

Everything here is pure and in the room's frame.
"""

from __future__ import annotations

import math

from hfsm_behaviours.room.claims import NEAR, Rect
from hfsm_behaviours.room.walks import BODY, CELL, Point, Scene, samples

MARGIN = 0.25  # metres a waiting robot's centre keeps outside a corridor (about its half width)
REACH = 3.0  # metres at most a waiting robot steps aside


def _clear_line(scene: Scene, a: Point, b: Point) -> bool:
    """Whether the straight line from a to b keeps `BODY` m off every table's top (past its start)."""
    return not any(t.contains(p, BODY) for p in samples(a, b)[1:] for t in scene.tables)


def in_the_way(scene: Scene, p: Point, busy: tuple[Rect, ...] = (), near: float = NEAR) -> bool:
    """Whether a robot waiting at `p` stands in a corridor of the `scene` or within `near` m of a
    `busy` table's top (a table still to be carried, not the robot's own)."""
    return scene.in_corridor(p, MARGIN) or any(t.contains(p, near) for t in busy)


def aside(scene: Scene, me: Point, reach: float = REACH, busy: tuple[Rect, ...] = (),
          near: float = NEAR) -> Point:
    """`me` when it is not in the way (`in_the_way`); else the nearest point of a `CELL` grid round
    it, within `reach` m, that is free (walls, tops, robots: `Scene.blocked`), not in the way, and
    reached on a straight line clear of the tables' tops; `me` when there is none."""
    if not in_the_way(scene, me, busy, near):
        return me
    steps = int(reach / CELL)
    spots = sorted(((me[0] + i * CELL, me[1] + j * CELL) for i in range(-steps, steps + 1)
                    for j in range(-steps, steps + 1) if 0 < math.hypot(i, j) * CELL <= reach),
                   key=lambda p: (round(math.dist(p, me), 6), p))
    for p in spots:
        if not scene.blocked(p) and not in_the_way(scene, p, busy, near) and _clear_line(scene, me, p):
            return (round(p[0], 4), round(p[1], 4))
    return me
