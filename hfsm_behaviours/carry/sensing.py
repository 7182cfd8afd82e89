"""What the carrying robot senses, in one call each: turn the head, take one image, measure.

Thin wrappers over `hfsm_sim.perception` (edge, reach, walls) for the primitives of this package;
every angle is a head pose the primitive passes in (its params), never a constant buried here.
"""

from __future__ import annotations

from hfsm_behaviours.body import Body
from hfsm_sim.perception import NearEdge, SideExtent, WallSeen, near_edge, side_extent, wall_to_side


def side_sign(side: str) -> float:
    """+1 for 'left', -1 for 'right' (the body frame's y axis)."""
    if side not in ("left", "right"):
        raise ValueError(f"side must be 'left' or 'right', not {side!r}")
    return 1.0 if side == "left" else -1.0


def other_side(side: str) -> str:
    return "right" if side_sign(side) > 0 else "left"


def edge(body: Body, pitch: float) -> NearEdge:
    """The table's near long edge through the down camera, the head straight and pitched."""
    body.look(0.0, pitch)
    return near_edge(body.image("down"), body.camera("down"))


def extent(body: Body, side: str, yaw: float, pitch: float, turn: float = 0.0) -> SideExtent:
    """How far the table top reaches to `side` along its near edge (`turn`: that edge's angle,
    see `NearEdge.turn`), looking that way by `yaw` (rad, > 0)."""
    body.look(side_sign(side) * abs(yaw), pitch)
    return side_extent(body.image("forward"), body.camera("forward"), side, turn)


def wall(body: Body, side: str, yaw: float, pitch: float) -> WallSeen:
    """The wall to `side`, looking that way (and a little back) by `yaw` (rad, > 0)."""
    body.look(side_sign(side) * abs(yaw), pitch)
    return wall_to_side(body.image("forward"), body.camera("forward"), side)
