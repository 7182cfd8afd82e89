"""Where a waiting robot stands out of the way of the carrying pairs.

A spare, or a robot idle after its table, waits where it happens to be (clear_room's `wait`). Standing
in a table's claimed carry corridor it blocks that table: the pair's steps are held (the table's
legs, below the waiting robot's range finder when the table is landed, push into it), and a leader
whose steps are held at once takes the block for the wall (generated room walls-34001: the spare r5,
waiting where it started, stopped table1 1.2 m short of its wall, and the pair said it was there).
So it first steps to the nearest point out of every corridor of a table not yet done.

Everything here is pure and in the room's frame.
"""

from __future__ import annotations

import math

from hfsm_behaviours.room.walks import BODY, CELL, Point, Scene, samples

MARGIN = 0.25  # metres a waiting robot's centre keeps outside a corridor (about its half width)
REACH = 3.0  # metres at most a waiting robot steps aside


def _clear_line(scene: Scene, a: Point, b: Point) -> bool:
    """Whether the straight line from a to b keeps `BODY` m off every table's top (past its start)."""
    return not any(t.contains(p, BODY) for p in samples(a, b)[1:] for t in scene.tables)


def aside(scene: Scene, me: Point, reach: float = REACH) -> Point:
    """`me` when it stands in no corridor of the `scene`; else the nearest point of a `CELL` grid
    round it, within `reach` m, that is free (walls, tops, robots: `Scene.blocked`), in no corridor,
    and reached on a straight line clear of the tables' tops; `me` when there is none."""
    if not scene.in_corridor(me, MARGIN):
        return me
    steps = int(reach / CELL)
    spots = sorted(((me[0] + i * CELL, me[1] + j * CELL) for i in range(-steps, steps + 1)
                    for j in range(-steps, steps + 1) if 0 < math.hypot(i, j) * CELL <= reach),
                   key=lambda p: (round(math.dist(p, me), 6), p))
    for p in spots:
        if not scene.blocked(p) and not scene.in_corridor(p, MARGIN) and _clear_line(scene, me, p):
            return (round(p[0], 4), round(p[1], 4))
    return me
