"""The assistant's first moves (Figure 7): Look for leader, Clear way."""

from __future__ import annotations

import math

from behaviours.approach.frames import bearing_to, body_to_odom
from behaviours.approach.navigate import unit
from behaviours.approach.sight import own_colour, scan_for_robot, see_table
from behaviours.body import Body
from hfsm.primitive import Context, Outcome, primitive
from sim.perception import find_robots, find_table, is_below

LEADER_YAWS = [0.0, 0.9, -0.9, 1.8, -1.8]


@primitive(outcomes=["found", "not_found"], outputs=["bearing", "distance"], world="sim")
def look_for_leader(ctx: Context, *, pitch: float = 0.3) -> Outcome:
    """Turn the head until the other robot (a robot colour that is not that of our own
    hands) is in view; its bearing (body frame) and the ground distance to its feet."""
    body = Body(ctx)
    seen = scan_for_robot(body, LEADER_YAWS, pitch, own_colour(body))
    body.look(0.0, pitch)
    if not seen.found:
        return Outcome("not_found")
    return Outcome("found", bearing=seen.bearing, distance=seen.distance)


@primitive(outcomes=["cleared"], outputs=["moved"], world="sim")
def clear_way(ctx: Context, *, leader_bearing: float = 0.0, leader_distance: float = -1.0,
              distance: float = 0.5, pitch: float = 0.3) -> Outcome:
    """Move out of the leader's way: unless the leader stands behind the table (the table's
    blob below the leader's), walk `distance` metres away from both the table (ahead) and
    the leader (`leader_distance` < 0: not seen), then face the table again."""
    body = Body(ctx)
    table = see_table(body, 0.0, pitch)
    if table is not None and leader_distance >= 0 and leader_behind_table(body, pitch):
        return Outcome("cleared", moved=0.0)
    pose = body.odometry()
    table_point = body_to_odom(pose, (table.distance if table else 1.0, 0.0))
    ax, ay = 1.0, 0.0
    if leader_distance >= 0:
        ax, ay = ax + math.cos(leader_bearing), ay + math.sin(leader_bearing)
    away = unit(-ax, -ay)
    body.turn(math.atan2(away[1], away[0]))
    body.walk(distance)
    body.turn(bearing_to(body.odometry(), table_point))
    return Outcome("cleared", moved=distance)


def leader_behind_table(body: Body, pitch: float) -> bool:
    """Section 3.5: the leader stands behind the table if the table blob is below its blob."""
    own = own_colour(body)
    body.look(0.0, pitch)
    image = body.image("forward")
    table = find_table(image)
    return any(is_below(table, b) for i, b in enumerate(find_robots(image)) if i != own)
