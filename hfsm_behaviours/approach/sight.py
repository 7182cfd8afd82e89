"""What a robot sees, put in its odometry frame: the table blob, the table top, the other robot."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from hfsm_behaviours.approach.frames import Point, body_to_odom, distance
from hfsm_behaviours.body import Body
from hfsm_sim.perception import (
    DEFAULT_CONFIG,
    NO_RECT,
    Blob,
    CameraModel,
    TableRect,
    TableSeen,
    blob_ground,
    find_robot_parts,
    find_robots,
    find_table,
    fit_rect,
    is_below,
    outline_points,
    pick_table,
    pixel_bearing,
    see_tables,
)

HEAD_YAW_LIMIT = 2.0  # rad; within the NAO's +-119.5 deg


@dataclass(frozen=True)
class TableSighting:
    """The table blob in one image, its bearing (body frame, head yaw included) and the
    ground distance to its lowest pixel."""

    blob: Blob
    bearing: float
    distance: float
    clipped: bool


@dataclass(frozen=True)
class RobotSighting:
    """Another robot: where its lowest pixel meets the floor, in the odometry frame."""

    found: bool
    position: Point = (math.nan, math.nan)
    bearing: float = math.nan
    distance: float = math.nan
    blob: Blob | None = None


NO_ROBOT = RobotSighting(found=False)


def clamp_yaw(yaw: float) -> float:
    return max(-HEAD_YAW_LIMIT, min(HEAD_YAW_LIMIT, yaw))


def see_table(body: Body, yaw: float, pitch: float) -> TableSighting | None:
    """Turn the head and look for the blue blob; None when it is not in view."""
    body.look(clamp_yaw(yaw), pitch)
    blob = find_table(body.image("forward"))
    if not blob.found:
        return None
    camera = body.camera("forward")
    ground = blob_ground(blob, camera)
    bearing = pixel_bearing(camera, blob.centroid[0], blob.centroid[1])
    return TableSighting(blob, bearing, ground.distance if ground.found else math.inf,
                         ground.clipped)


def named(table: Sequence[float] | None) -> Point | None:
    """A machine's `table` param, [x, y] in the robot's own start frame ([] or None: any table)."""
    return (float(table[0]), float(table[1])) if table else None


def see_named_table(body: Body, yaw: float, pitch: float, target: Point, gate: float) -> TableSeen | None:
    """Turn the head and look for the table seen nearest `target` (odometry frame), within
    `gate` metres, among every table in view."""
    body.look(clamp_yaw(yaw), pitch)
    seen = see_tables([(body.image("forward"), body.camera("forward"))])
    return pick_table(seen, target, gate)


def ground_distance(body: Body, point: Point) -> float:
    return distance(body.odometry()[:2], point)


def look_around(body: Body, centre: float, spread: float, pitch: float, views: int
                ) -> list[tuple[np.ndarray, CameraModel]]:
    """Forward images (with the camera model of each) from `views` head yaws spread around the
    bearing `centre` (body frame). The robot stands still meanwhile, so every view takes the
    pose it had when it began: the odometry's drift while the head turns moves no view."""
    pose = body.odometry()
    out = []
    for i in range(views):
        body.look(clamp_yaw(centre + spread * (i - (views - 1) / 2)), pitch)
        out.append((body.image("forward"), replace(body.camera("forward"), odom=pose)))
    return out


def observe_table(body: Body, centre: float, spread: float, pitch: float,
                  value_ratio: float = 0.9, views: int = 3) -> TableRect:
    """The table top as a rectangle in the odometry frame, from every top face seen in
    `views` head yaws spread around the bearing `centre` (body frame)."""
    points = [camera.to_odom(outline_points(image, camera, value_ratio))
              for image, camera in look_around(body, centre, spread, pitch, views)]
    if sum(len(p) for p in points) == 0:
        return NO_RECT
    return fit_rect(points)


def observe_tables(body: Body, centre: float, spread: float, pitch: float,
                   value_ratio: float = 0.9, views: int = 3) -> list[TableSeen]:
    """Every table seen in those views, told apart (odometry frame, nearest first)."""
    return see_tables(look_around(body, centre, spread, pitch, views), value_ratio)


def own_colour(body: Body, pitch: float = 0.5) -> int:
    """Which robot colour is this robot: the colour of its own hands, seen from above; -1 when
    no hands are seen (then no colour is taken for its own)."""
    body.look(0.0, pitch)
    areas = [b.area_px if b.found else 0 for b in find_robots(body.image("down"))]
    return int(np.argmax(areas)) if max(areas, default=0) > 0 else -1


def other_robot(i: int, own: int, only: int = -1) -> bool:
    """Robot colour `i` is the one looked for: colour `only` (a partner's, as it said it), or
    with `only` < 0 any colour but this robot's own."""
    return i == only if only >= 0 else i != own


def robot_sighting(body: Body, camera: CameraModel, blob: Blob) -> RobotSighting:
    """Another robot's blob put on the floor: where its lowest pixel meets it, odometry frame."""
    ground = blob_ground(blob, camera)
    bearing = pixel_bearing(camera, blob.lowest_u, blob.lowest_row + 1.0)
    if not ground.found:
        return RobotSighting(True, bearing=bearing, distance=math.inf, blob=blob)
    return RobotSighting(True, body_to_odom(body.odometry(), (ground.x, ground.y)), bearing,
                         ground.distance, blob)


def nearest_of_colour(body: Body, image: np.ndarray, colour: int, near: Point) -> RobotSighting:
    """Of the robots of colour `colour` in this image, told apart (`find_robot_parts`), the one
    standing nearest `near` (odometry frame): colours repeat beyond ten robots, and a partner is
    known to stand near its table."""
    camera = body.camera("forward")
    parts = find_robot_parts(image, DEFAULT_CONFIG.robot_colours[colour])
    seen = [robot_sighting(body, camera, b) for b in parts]
    seen = [r for r in seen if r.blob is not None and r.blob.found]
    if not seen:
        return NO_ROBOT
    return min(seen, key=lambda r: off(r, near))


def see_robot(body: Body, yaw: float, pitch: float, own: int, only: int = -1,
              near: Point | None = None) -> RobotSighting:
    """The largest blob of another robot's colour (of colour `only` if >= 0) in this view, if any;
    with `only` and `near`, the robot of that colour nearest `near` (`nearest_of_colour`)."""
    body.look(clamp_yaw(yaw), pitch)
    image = body.image("forward")
    if only >= 0 and near is not None:
        return nearest_of_colour(body, image, only, near)
    robots = enumerate(find_robots(image))
    blobs = [b for i, b in robots if other_robot(i, own, only) and b.found]
    if not blobs:
        return NO_ROBOT
    return robot_sighting(body, body.camera("forward"), max(blobs, key=lambda b: b.area_px))


def off(seen: RobotSighting, near: Point) -> float:
    """How far a sighting stands from `near` (infinite when its feet were not on the floor)."""
    return distance(seen.position, near) if math.isfinite(seen.position[0]) else math.inf


def scan_for_robot(body: Body, yaws: Sequence[float], pitch: float, own: int,
                   only: int = -1, near: Point | None = None, close: float = 1.5) -> RobotSighting:
    """Turn the head through `yaws` until a robot (of colour `only`) is seen. With `only` and
    `near`, a robot of that colour seen more than `close` m from `near` may be another robot
    wearing it (colours repeat beyond ten robots): the scan goes on, and of all those seen the one
    nearest `near` is taken."""
    others = []
    for yaw in yaws:
        seen = see_robot(body, yaw, pitch, own, only, near)
        if not seen.found:
            continue
        if only < 0 or near is None or off(seen, near) <= close:
            return seen
        others.append(seen)
    return min(others, key=lambda s: off(s, near)) if others and near is not None else NO_ROBOT


def leader_behind_table(body: Body, pitch: float, own: int, only: int = -1,
                        near: Point | None = None) -> bool:
    """Section 3.5: the other robot (of colour `only` if >= 0; with `near`, the one of that colour
    nearest it) stands behind the table if the table's blob is below its blob (looking straight
    ahead)."""
    body.look(0.0, pitch)
    image = body.image("forward")
    table = find_table(image)
    if only >= 0 and near is not None:
        leader = nearest_of_colour(body, image, only, near)
        return leader.blob is not None and is_below(table, leader.blob)
    return any(is_below(table, b) for i, b in enumerate(find_robots(image)) if other_robot(i, own, only))
