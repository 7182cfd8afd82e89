"""Primitives that drive a robot by velocity commands to points of its odometry frame: for the
light bodies of team scenarios (whose odometry is in the room's frame), usable by any body."""

from __future__ import annotations

from hfsm.primitive import Primitive
from hfsm_behaviours.drive.along import go_along, localise, odometry_pose
from hfsm_behaviours.drive.back import back_away
from hfsm_behaviours.drive.goto import go_to, hold, stop

PRIMITIVES: tuple[Primitive, ...] = (go_to, go_along, odometry_pose, localise, hold, stop, back_away)
