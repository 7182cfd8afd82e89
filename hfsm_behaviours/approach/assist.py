"""The assistant's first moves (Figure 7): Look for leader, Clear way."""

from __future__ import annotations

import math

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import bearing_to, body_to_odom
from hfsm_behaviours.approach.sight import leader_behind_table, named, own_colour, scan_for_robot, see_table
from hfsm_behaviours.body import Body

LEADER_YAWS = [0.0, 0.9, -0.9, 1.8, -1.8]


@primitive(outcomes=["colour"], outputs=["colour"], world="sim")
def sense_own_colour(ctx: Context) -> Outcome:
    """This robot's colour, an index of the robot colours: the colour of its own hands, seen
    from above (-1: none seen). A robot says it to its partner, which then looks for it."""
    return Outcome("colour", colour=own_colour(Body(ctx)))


@primitive(outcomes=["found", "not_found"], outputs=["bearing", "distance"], world="sim")
def look_for_leader(ctx: Context, *, pitch: float = 0.3, colour: int = -1,
                    table: list[float] | None = None) -> Outcome:
    """Turn the head until the other robot (a robot colour that is not that of our own
    hands; with `colour` >= 0, the leader's colour as it said it) is in view; its bearing (body
    frame) and the ground distance to its feet. With a `colour` and a `table` ([x, y], own start
    frame), of the robots of that colour in view the one nearest the table (colours repeat beyond
    ten robots)."""
    body = Body(ctx)
    seen = scan_for_robot(body, LEADER_YAWS, pitch, own_colour(body), colour, named(table))
    body.look(0.0, pitch)
    if not seen.found:
        return Outcome("not_found")
    return Outcome("found", bearing=seen.bearing, distance=seen.distance)


@primitive(outcomes=["cleared"], outputs=["moved"], world="sim")
def clear_way(ctx: Context, *, leader_bearing: float = 0.0, leader_distance: float = -1.0,
              distance: float = 0.6, sideways: float = 1.0, pitch: float = 0.3,
              leader_colour: int = -1, table: list[float] | None = None) -> Outcome:
    """Move out of the leader's way: unless the leader stands behind the table (the table's
    blob below the leader's), walk `distance` metres away from the table (ahead), turned
    `sideways` rad from straight back towards the side away from the leader
    (`leader_distance` < 0: not seen, straight back); then face the table again. With a
    `leader_colour` (>= 0), only a robot of that colour is the leader; with a `table` too, the
    one of that colour nearest the table."""
    body = Body(ctx)
    near = named(table)
    seen = see_table(body, 0.0, pitch)
    both_seen = leader_distance >= 0 and seen is not None
    if both_seen and leader_behind_table(body, pitch, own_colour(body), leader_colour, near):
        return Outcome("cleared", moved=0.0)
    pose = body.odometry()
    table_point = body_to_odom(pose, (seen.distance if seen else 1.0, 0.0))
    heading = math.pi
    if leader_distance >= 0:
        heading = -math.copysign(math.pi - sideways, leader_bearing)
    body.turn(heading)
    body.walk(distance)
    body.turn(bearing_to(body.odometry(), table_point))
    return Outcome("cleared", moved=distance)
