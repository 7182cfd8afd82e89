"""Go to table (section 3.4, Figure 5): walk to the nearest corner of the table.

The nearest corner stands on the nearest leg, whose foot is the table blob's lowest pixel.
The robot turns until that pixel is in the central band of the image, walks while it stays
there, and stops before the table when the lowest pixel passes `near` of the image height.
"""

from __future__ import annotations

from behaviours.body import Body
from hfsm.primitive import Context, Outcome, primitive
from sim.perception import find_table, pixel_bearing


@primitive(outcomes=["at_corner", "lost"], failures=["lost"], outputs=["bearing"], world="sim")
def go_to_table(ctx: Context, *, margin: float = 0.2, near: float = 0.8, pitch: float = 0.5,
                period: float = 0.25, gain: float = 1.0) -> Outcome:
    """Walk to the nearest corner, keeping it within `margin` of the image centre; stop when
    the table's lowest pixel is more than `near` down the image. `lost`: no table in view."""
    body = Body(ctx)
    body.look(0.0, pitch)
    try:
        while True:
            blob = find_table(body.image("forward"))
            if not blob.found:
                return Outcome("lost")
            camera = body.camera("forward")
            bearing = pixel_bearing(camera, blob.lowest_u, blob.lowest_row + 1.0)
            if blob.lowest_row + 1 > near * camera.height:
                return Outcome("at_corner", bearing=bearing)
            centred = abs(blob.lowest_u - camera.cx) <= margin * camera.width / 2
            forward = body.motion.forward_max if centred else 0.0
            ctx.robot.set_velocity(forward, 0.0, gain * bearing)
            ctx.wait(period)
    finally:
        ctx.robot.stop()
