"""The plug-in's primitives: Python functions that block, as their author sees them."""

from __future__ import annotations

from hfsm.primitive import Context, Outcome, primitive


@primitive(outcomes=["done", "failure"], outputs=["counted"])
def count_down(ctx: Context, *, start: int = 3, every: float = 0.5) -> Outcome:
    """Count down from `start`, one number every `every` seconds; `failure` when `start` < 0."""
    if start < 0:
        return Outcome("failure")
    for n in range(start, 0, -1):
        ctx.log.info("%s: %d", ctx.agent, n)
        ctx.wait(every)  # the interpreter resumes it tick by tick; a timer may cancel it here
    return Outcome("done", counted=start)
