"""The parts of Look for table (section 3.1): scan with the head, spin, wander, centre the table."""

from __future__ import annotations

import math

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import bearing_to
from hfsm_behaviours.approach.sight import ground_distance, named, see_named_table, see_table
from hfsm_behaviours.body import Body
from hfsm_behaviours.drive.things import BEAMS, things


@primitive(outcomes=["seen", "not_seen"], outputs=["bearing", "distance"], world="sim")
def scan_for_table(ctx: Context, *, yaws: list[float] | None = None, pitch: float = 0.3,
                   table: list[float] | None = None, gate: float = 0.6) -> Outcome:
    """Turn the head through `yaws` (rad, left +; default left, ahead, right) until the
    blue table is in view; its bearing (body frame) and ground distance. With a `table`
    ([x, y], own start frame), only the table seen nearest it within `gate` m counts, and the
    bearing and distance are to its centre."""
    body = Body(ctx)
    target = named(table)
    for yaw in yaws if yaws is not None else [0.9, 0.0, -0.9]:
        if target is not None:
            picked = see_named_table(body, float(yaw), pitch, target, gate)
            if picked is not None:
                return Outcome("seen", bearing=bearing_to(body.odometry(), picked.position),
                               distance=ground_distance(body, picked.position))
            continue
        seen = see_table(body, float(yaw), pitch)
        if seen is not None:
            return Outcome("seen", bearing=seen.bearing, distance=seen.distance)
    return Outcome("not_seen")


@primitive(outcomes=["done"], world="sim")
def spin_on_the_spot(ctx: Context, *, degrees: float = 180.0) -> str:
    """Turn the body on the spot, left positive."""
    Body(ctx).turn(math.radians(degrees))
    return "done"


@primitive(outcomes=["done", "bumped", "blocked"], world="sim")
def walk_randomly(ctx: Context, *, distance: float = 1.0, step: float = 0.25, look: float = 0.0) -> str:
    """Turn to a random heading (ctx.rng) and walk about `distance` metres; stop on a bump. With
    `look` > 0 (a room, other robots about), the range finder is read before each step: the heading
    drawn is turned by the least multiple of 45 degrees that leaves no thing it sees in the way
    within `look` m (`blocks`), none: `blocked` without walking; a thing come into the way ends the
    walk `blocked` before the step that would meet it."""
    body = Body(ctx)
    turn = ctx.rng.uniform(-math.pi, math.pi)
    if look > 0.0:
        seen = _things(ctx, look)
        free = [turn + k * math.pi / 4 for k in (0, 1, -1, 2, -2, 3, -3, 4)
                if not blocks(_turned(seen, turn + k * math.pi / 4), look)]
        if not free:
            return "blocked"
        turn = free[0]
    body.turn(turn)
    walked = 0.0
    while walked < distance:
        if look > 0.0 and blocks(_things(ctx, look), look):
            return "blocked"
        body.walk(min(step, distance - walked))
        walked += step
        if ctx.robot.bumped():
            body.walk(-step)
            return "bumped"
    return "done"


LANE = 0.4  # metres either side of a walk's line within which a thing sensed is in its way


def blocks(seen: list[tuple[float, float]], look: float) -> bool:
    """Whether a thing `seen` ((forward, left) m, body frame) lies in the way ahead within `look` m."""
    return any(0.0 < f < look and abs(left) < LANE for f, left in seen)


def _turned(seen: list[tuple[float, float]], turn: float) -> list[tuple[float, float]]:
    """`seen` in the body frame the robot will have after turning by `turn` rad (left +)."""
    c, s = math.cos(turn), math.sin(turn)
    return [(c * f + s * left, -s * f + c * left) for f, left in seen]


def _things(ctx: Context, look: float) -> list[tuple[float, float]]:
    return things(ctx.robot.scan(BEAMS, look + 0.5), look + 0.4)


@primitive(outcomes=["centred", "lost"], failures=["lost"], outputs=["distance"], world="sim")
def centre_table(ctx: Context, *, bearing: float = 0.0, pitch: float = 0.3, margin: float = 0.2,
                 tries: int = 6, table: list[float] | None = None, gate: float = 0.6) -> Outcome:
    """Turn the body by `bearing`, then until the table's blob sits in the central band
    (`margin` of the image width); the ground distance to its lowest pixel. With a `table`
    ([x, y], own start frame): until the centre of the table seen nearest it (within `gate`
    m) is in that band; the ground distance to that centre."""
    body = Body(ctx)
    body.turn(bearing)
    target = named(table)
    if target is not None:
        half_band = math.atan(margin * body.camera().width / 2 / body.camera().fx)
        for _ in range(tries):
            picked = see_named_table(body, 0.0, pitch, target, gate)
            if picked is None:
                return Outcome("lost")
            turn = bearing_to(body.odometry(), picked.position)
            if abs(turn) <= half_band:
                return Outcome("centred", distance=ground_distance(body, picked.position))
            body.turn(turn)
            target = picked.position
        return Outcome("lost")
    for _ in range(tries):
        seen = see_table(body, 0.0, pitch)
        if seen is None:
            return Outcome("lost")
        width = body.camera().width
        if abs(seen.blob.centroid[0] - width / 2) <= margin * width / 2:
            return Outcome("centred", distance=seen.distance)
        body.turn(seen.bearing)
    return Outcome("lost")
