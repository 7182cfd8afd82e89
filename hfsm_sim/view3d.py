"""The room in 3-D, as the paper's Figure 2 shows it: a perspective camera high over one corner,
shaded and lit, with each robot's label over its head and a banner while the table is lifted.

A picture for people (videos and final pictures), rendered from the simulator's state: robots never
see it.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import cv2
import numpy as np
import pybullet as p

if TYPE_CHECKING:
    from hfsm_sim.world import World

FOV = 50.0
LIGHT = {"lightDirection": [-2.0, -3.0, 5.0], "lightColor": [1.0, 1.0, 1.0], "lightDistance": 8.0,
         "lightAmbientCoeff": 0.55, "lightDiffuseCoeff": 0.55, "lightSpecularCoeff": 0.15}
LIFTED = 0.02  # m above resting height: the table counts as lifted


def camera(width: float, depth: float, size: tuple[int, int]) -> tuple[list[float], list[float]]:
    """View and projection matrices of a camera above the room's south-west corner, looking at
    its middle from far enough to see all four walls."""
    extent = max(width, depth)
    eye = [-0.35 * width, -0.75 * depth, 1.25 * extent]
    view = p.computeViewMatrix(eye, [0.0, 0.08 * depth, 0.0], [0.0, 0.0, 1.0])
    proj = p.computeProjectionMatrixFOV(FOV, size[0] / size[1], 0.1, 4.0 * extent)
    return list(view), list(proj)


def project(view: list[float], proj: list[float], point: tuple[float, float, float],
            size: tuple[int, int]) -> tuple[int, int] | None:
    """Where a world point falls in the picture (pixels), or None if it is behind the camera."""
    v = np.array(view).reshape(4, 4).T
    q = np.array(proj).reshape(4, 4).T
    clip = q @ v @ np.array([*point, 1.0])
    if clip[3] <= 0:
        return None
    x, y = clip[0] / clip[3], clip[1] / clip[3]
    return int((x + 1) / 2 * size[0]), int((1 - y) / 2 * size[1])


def perspective(world: World, size: tuple[int, int] = (640, 480),
                labels: Mapping[str, str] | None = None) -> np.ndarray:
    """The room in 3-D (BGR), each robot named (and `labels[name]` beside it), the table's state."""
    room = world.scenario.room
    view, proj = camera(room.width, room.depth, size)
    _, _, rgba, _, _ = p.getCameraImage(size[0], size[1], view, proj, shadow=0,
                                        renderer=p.ER_TINY_RENDERER, flags=p.ER_NO_SEGMENTATION_MASK,
                                        physicsClientId=world.client, **LIGHT)
    image = cv2.cvtColor(np.asarray(rgba, np.uint8).reshape(size[1], size[0], 4)[:, :, :3], cv2.COLOR_RGB2BGR)
    for name in world.robots:
        x, y, _ = world.truth.robot_pose(name)
        at = project(view, proj, (x, y, 0.75), size)
        if at is not None:
            label(image, robot_text(name, labels), at)
    status(image, world)
    return image


def robot_text(name: str, labels: Mapping[str, str] | None) -> str:
    """A robot's name, with `labels[name]` beside it when there is one."""
    extra = labels.get(name) if labels else None
    return f"{name}: {extra}" if extra else name


def label(image: np.ndarray, text: str, at: tuple[int, int]) -> None:
    """White text on a dark box, centred over `at`, kept inside the picture."""
    font, scale = cv2.FONT_HERSHEY_SIMPLEX, 0.42
    (w, h), base = cv2.getTextSize(text, font, scale, 1)
    x = min(max(2, at[0] - w // 2), image.shape[1] - w - 2)
    y = min(max(h + 4, at[1]), image.shape[0] - base - 2)
    cv2.rectangle(image, (x - 2, y - h - 3), (x + w + 2, y + base), (30, 30, 30), -1)
    cv2.putText(image, text, (x, y), font, scale, (255, 255, 255), 1, cv2.LINE_AA)


def status(image: np.ndarray, world: World) -> None:
    """The time, and whether the table is lifted or dropped, along the picture's top."""
    lifts = [world.truth.table_pose(i)[2] for i in range(len(world.truth.tables))]
    lift = max(lifts, default=0.0)
    state = "TABLE DROPPED" if world.dropped else "table lifted" if lift >= LIFTED else \
        "table on the floor" if lifts else ""
    minutes, seconds = divmod(world.time, 60)
    text = f"t = {int(minutes):02d}:{seconds:04.1f}   {state}"
    colour = (0, 0, 200) if world.dropped else (0, 120, 0) if lift >= LIFTED else (60, 60, 60)
    cv2.rectangle(image, (0, 0), (image.shape[1], 22), (245, 245, 245), -1)
    cv2.putText(image, text, (8, 16), cv2.FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv2.LINE_AA)
