"""Position to centre of table side (section 3.4) and Go to the lifting point."""

from __future__ import annotations

import math

import numpy as np

from hfsm.primitive import Context, Outcome, primitive
from hfsm_behaviours.approach.frames import Side, from_table_frame, sides, table_frame
from hfsm_behaviours.approach.navigate import Look, Tolerance, align_to_side, look_at_table, walk_to
from hfsm_behaviours.approach.sight import named
from hfsm_behaviours.body import Body
from hfsm_sim.perception.table_rect import TableRect, outline_pieces


def facing_long_side(rect: TableRect, body: Body) -> Side:
    """The long side on the robot's side of the table's long axis."""
    _, y = table_frame(rect, body.odometry()[:2])
    return sides(rect)[0 if y >= 0 else 1]


def entry_point(rect: TableRect, body: Body, gap: float) -> tuple[float, float]:
    """Where to join the line `gap` out from the robot's long side: straight out in front of
    the side, or at its corner when the robot is beyond the side's end."""
    x, y = table_frame(rect, body.odometry()[:2])
    half = rect.length / 2
    if abs(x) <= half:
        return from_table_frame(rect, (x, math.copysign(rect.width / 2 + gap, y)))
    return from_table_frame(rect, (math.copysign(half + gap, x), math.copysign(rect.width / 2 + gap, y)))


@primitive(outcomes=["at_side_centre", "not_aligned", "lost"], failures=["not_aligned", "lost"],
           outputs=["length", "width"], world="sim")
def position_to_centre_of_table_side(
        ctx: Context, *, gap: float = 0.35, pitch: float = 0.3, spread: float = 0.7,
        along_tolerance: float = 0.03, out_tolerance: float = 0.03, yaw_tolerance: float = 0.05,
        tries: int = 4, table: list[float] | None = None, gate: float = 0.6) -> Outcome:
    """From near a corner, look left, ahead and right to find the longer side, join the line
    `gap` metres out from it, turn the shoulders parallel to it and crab to its middle. With a
    `table` ([x, y], own start frame): the table seen nearest it, within `gate` m."""
    body = Body(ctx)
    look = Look(pitch=pitch, spread=spread, target=named(table), gate=gate)
    rect = look_at_table(body, None, look)
    if not rect.found:
        return Outcome("lost")
    walk_to(body, entry_point(rect, body, gap))
    tol = Tolerance(along_tolerance, out_tolerance, yaw_tolerance)
    side = facing_long_side(rect, body)
    rect, side, ok = align_to_side(body, rect, side.middle, gap, look, tol, tries)
    return Outcome("at_side_centre" if ok else "not_aligned", length=rect.length, width=rect.width)


def edge_ahead(body: Body, pitch: float, band: float) -> float | None:
    """Distance (body frame x) to the nearest table-top edge straight ahead, within
    `band` metres either side, seen with the down camera (forward camera if out of view).
    An edge ahead runs across the band within one top face: a piece of outline on one side of it
    only is not the top's edge (a short table's legs in the corners of the down view, put on the
    plane of the top, look nearer than the top)."""
    for camera in ("down", "forward"):
        body.look(0.0, pitch)
        seen = []
        for pts, _ in outline_pieces(body.image(camera), body.camera(camera)):
            ahead = pts[np.abs(pts[:, 1]) <= band]
            if len(ahead) and ahead[:, 1].min() <= -band / 2 and ahead[:, 1].max() >= band / 2:
                seen.append(float(ahead[:, 0].min()))
        if seen:
            return min(seen)
    return None


@primitive(outcomes=["at_lifting_point", "lost"], failures=["lost"], outputs=["edge"], world="sim")
def go_to_the_lifting_point(ctx: Context, *, hands: float = 0.17, grip: float = 0.06,
                            tolerance: float = 0.015, pitch: float = 0.5, band: float = 0.08,
                            tries: int = 4) -> Outcome:
    """Lower the arms, then step in until the hands (`hands` m ahead of the body centre) are
    `grip` m under the table's edge, without touching the table."""
    body = Body(ctx)
    body.arms(None)
    edge = math.nan
    for _ in range(tries):
        seen = edge_ahead(body, pitch, band)
        if seen is None:
            return Outcome("lost")
        edge = seen
        error = edge - (hands - grip)
        if abs(error) <= tolerance:
            break
        body.walk(error)
    return Outcome("at_lifting_point", edge=edge)
