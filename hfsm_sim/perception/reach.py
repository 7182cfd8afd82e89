"""How far the table top reaches to one side (Behaviour 2, "look left and right to determine
which side is the longest"), with the head turned that way.

Every table pixel is put on the plane of the top; pixels that are not on the top (rim, legs)
land nearer to the camera, so the farthest point to that side is the top's corner. Pixels past
a gap of `extent_gap` along the edge, among all table pixels or among the top face's alone (a
near table's legs and rim, projected on this plane, may fill the gap), belong to another table
of the room, so the reach stops before it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from hfsm_sim.perception.blobs import clean_mask
from hfsm_sim.perception.camera import CameraModel
from hfsm_sim.perception.colour import table_mask, top_face
from hfsm_sim.perception.config import DEFAULT_CONFIG, PerceptionConfig


@dataclass(frozen=True)
class SideExtent:
    """How far (m) the table top reaches to one side of the body (`lateral`, body y, >= 0),
    and whether the table runs out of the view on that side (then it reaches further)."""

    found: bool
    lateral: float = math.nan
    clipped: bool = False


NO_EXTENT = SideExtent(False)


def side_extent(image: np.ndarray, camera: CameraModel, side: str, turn: float = 0.0,
                cfg: PerceptionConfig = DEFAULT_CONFIG) -> SideExtent:
    """How far the table top reaches to `side` ('left' or 'right'), measured along the near
    edge: `turn` is that edge's `NearEdge.turn` (0: the edge runs along the body's y axis)."""
    mask, _ = clean_mask(table_mask(image, cfg), cfg)
    vs, us = np.nonzero(mask)
    if us.size == 0:
        return NO_EXTENT
    xs, ys, ok = camera.to_plane(us + 0.5, vs + 0.5, cfg.table_top_height)
    if not ok.any():
        return NO_EXTENT
    sign = 1.0 if side == "left" else -1.0
    along = sign * (-math.sin(turn) * xs + math.cos(turn) * ys)
    top = ok & top_face(image, cfg=cfg)[vs, us]
    ok, top = _this_table(math.cos(turn) * xs + math.sin(turn) * ys, ok, top, cfg.extent_gap)
    if not ok.any():
        return NO_EXTENT
    cuts = [cut for cut in (_before_gap(along[ok], cfg.extent_gap), _before_gap(along[top], cfg.extent_gap))
            if cut is not None]
    if cuts:
        return SideExtent(True, lateral=max(0.0, min(cuts)), clipped=False)
    outer = mask[:, 0] if side == "left" else mask[:, -1]
    far = along[top] if top.any() else along[ok]
    return SideExtent(True, lateral=max(0.0, float(np.max(far))), clipped=bool(outer.any()))


def _this_table(across: np.ndarray, ok: np.ndarray, top: np.ndarray,
                gap: float) -> tuple[np.ndarray, np.ndarray]:
    """The pixels of the table ahead whose near edge is nearest, by their distance `across` the edge
    (ahead of the body > 0): its top face runs from the near edge to the far edge with no gap wider
    than `gap`, a top beyond such a gap is another table's (one standing behind this one, its end
    reaching past this table's end, lengthened the side: generated room close-34000), and so is a
    top more than `gap` behind the body (the held table's top is ahead of it). Rims and legs project
    nearer than their top, so the far cut is taken from the tops alone."""
    ahead = np.sort(across[top & (across >= 0.0)])
    if not ahead.size:
        return ok, top
    gaps = np.nonzero(np.diff(ahead) > gap)[0]
    far = ahead[gaps[0]] if gaps.size else ahead[-1]
    keep = (across >= -gap) & (across <= far + gap / 2)
    return ok & keep, top & keep


def _before_gap(along: np.ndarray, gap: float) -> float | None:
    """The last value before the first gap wider than `gap` on the positive side, if any."""
    ordered = np.sort(along)
    gaps = np.nonzero((np.diff(ordered) > gap) & (ordered[1:] > 0.0))[0]
    return float(ordered[gaps[0]]) if gaps.size else None
