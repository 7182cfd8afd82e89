"""Going to a place of the odometry frame, for team tasks (TARARC's form up and move).

For robots told their start pose the odometry frame is the room's; otherwise it is the robot's own
start frame, and the places must be given in it.
"""

from __future__ import annotations

from behaviours.approach.frames import distance
from behaviours.approach.navigate import walk_to
from behaviours.body import Body
from hfsm.primitive import Context, Primitive, primitive


@primitive(outcomes=["arrived", "blocked"], failures=["blocked"], world="sim")
def go_to_place(ctx: Context, *, x: float, y: float, tolerance: float = 0.15, tries: int = 4) -> str:
    """Turn towards (x, y) (metres, odometry frame) and walk straight to it, again until within
    `tolerance`; `blocked` when `tries` walks leave it farther."""
    body = Body(ctx)
    for _ in range(tries):
        if distance(body.odometry()[:2], (x, y)) <= tolerance:
            return "arrived"
        walk_to(body, (x, y))
    return "arrived" if distance(body.odometry()[:2], (x, y)) <= tolerance else "blocked"


PRIMITIVES: tuple[Primitive, ...] = (go_to_place,)
