"""Go to table (section 3.4, Figure 5): walk to the nearest corner of the table.

The robot picks the nearest corner of the table top it sees and keeps to that corner (in its
odometry frame, so two equally near corners do not make it dither). It turns until the corner
is in the central band of the image, walks while it stays there, and stops before the table
when the table's lowest pixel passes `near` of the image height.
"""

from __future__ import annotations

import math

import numpy as np

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import Point, bearing_to, body_to_odom, distance, odom_to_body
from hfsm_behaviours.approach.sight import named, see_named_table
from hfsm_behaviours.body import Body
from hfsm_sim.perception import Blob, find_table, pixel_bearing
from hfsm_sim.perception.table_rect import table_rect


def corner_in_view(body: Body, held: Point | None) -> Point | None:
    """The top's corner (odometry frame) nearest to the held one, or to the robot."""
    rect = table_rect(body.image("forward"), body.camera("forward"))
    if not rect.found:
        return None
    pose = body.odometry()
    corners = [body_to_odom(pose, c) for c in rect.corners()]
    return min(corners, key=lambda c: distance(c, held if held else pose[:2]))


def steer_bearing(body: Body, blob: Blob, corner: Point | None) -> float:
    if corner is not None:
        return bearing_to(body.odometry(), corner)
    camera = body.camera("forward")
    return pixel_bearing(camera, blob.lowest_u, blob.lowest_row + 1.0)


def near_row_distance(body: Body, near: float) -> float:
    """Metres ahead on the floor seen `near` down the image, in its middle column."""
    camera = body.camera("forward")
    xs, _, ok = camera.to_plane(np.array([camera.width / 2]), np.array([near * camera.height]), 0.0)
    return float(xs[0]) if bool(ok[0]) else 0.0


def go_to_named_table(ctx: Context, body: Body, target: Point, gate: float, margin: float, near: float,
                      pitch: float, period: float, gain: float) -> Outcome:
    """go_to_table for the table seen nearest `target`: its nearest corner, held, until that
    corner is as near as the floor `near` down the image."""
    stop = near_row_distance(body, near)
    corner: Point | None = None
    try:
        while True:
            picked = see_named_table(body, 0.0, pitch, target, gate)
            if picked is None:
                return Outcome("lost")
            target = picked.position
            pose = body.odometry()
            corner = min(picked.rect.corners(), key=lambda c: distance(c, corner if corner else pose[:2]))
            bearing = bearing_to(pose, corner)
            if odom_to_body(pose, corner)[0] <= stop:
                return Outcome("at_corner", bearing=bearing)
            _steer(ctx, body, bearing, margin, gain, period)
    finally:
        ctx.robot.stop()


def _steer(ctx: Context, body: Body, bearing: float, margin: float, gain: float,
           period: float) -> None:
    """Turn towards `bearing`, walking only while it is within `margin` of the image centre."""
    half_band = math.atan(margin * body.camera().width / 2 / body.camera().fx)
    forward = body.motion.forward_max if abs(bearing) <= half_band else 0.0
    ctx.robot.set_velocity(forward, 0.0, gain * bearing)
    ctx.wait(period)


@primitive(outcomes=["at_corner", "lost"], failures=["lost"], outputs=["bearing"], world="sim")
def go_to_table(ctx: Context, *, margin: float = 0.2, near: float = 0.8, pitch: float = 0.3,
                period: float = 0.25, gain: float = 1.0, table: list[float] | None = None,
                gate: float = 0.6) -> Outcome:
    """Walk to the nearest corner, keeping it within `margin` of the image centre; stop when
    the table's lowest pixel is more than `near` down the image. `lost`: no table in view.
    With a `table` ([x, y], own start frame): the table seen nearest it within `gate` m, until
    its nearest corner is as near as the floor `near` down the image."""
    body = Body(ctx)
    body.look(0.0, pitch)
    target = named(table)
    if target is not None:
        return go_to_named_table(ctx, body, target, gate, margin, near, pitch, period, gain)
    corner: Point | None = None
    try:
        while True:
            blob = find_table(body.image("forward"))
            if not blob.found:
                return Outcome("lost")
            corner = corner_in_view(body, corner) or corner
            bearing = steer_bearing(body, blob, corner)
            if blob.lowest_row + 1 > near * body.camera().height:
                return Outcome("at_corner", bearing=bearing)
            _steer(ctx, body, bearing, margin, gain, period)
    finally:
        ctx.robot.stop()
