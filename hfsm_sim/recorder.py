"""Video of a run (H.264 MP4, VP9 WebM or GIF: `hfsm_sim.video`), top-down or in 3-D (`hfsm_sim.view3d`),
optionally with the robots' camera views, and a PNG of the last frame. The world calls `capture`
every `every` simulated seconds."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

import av
import cv2
import numpy as np

from hfsm_sim.light import LIGHT_BODY
from hfsm_sim.profile import ROBOT_COLOURS, TABLE_COLOUR
from hfsm_sim.robot import Robot
from hfsm_sim.video import VideoWriter
from hfsm_sim.view3d import label, perspective, robot_text, status

if TYPE_CHECKING:
    from hfsm_sim.world import World

FLOOR_BGR, WALL_BGR = (60, 80, 105), (215, 230, 235)


def _bgr(rgb: tuple[float, float, float], shade: float = 1.0) -> tuple[int, int, int]:
    return (int(rgb[2] * 255 * shade), int(rgb[1] * 255 * shade), int(rgb[0] * 255 * shade))


class Recorder:
    def __init__(self, path: str | Path, *, every: float = 0.5, size: int = 480,
                 cameras: bool = False, fps: float = 10.0, view: str = "top") -> None:
        if view not in ("top", "3d"):
            raise ValueError(f"a view is 'top' or '3d', not {view!r}")
        self.path = Path(path)
        self.every, self.size, self.cameras, self.fps, self.view = every, size, cameras, fps, view
        self._video = VideoWriter(self.path, fps)
        self._failed: str | None = None
        self.last: np.ndarray | None = None
        self.frames = 0

    def capture(self, world: World) -> None:
        if self.view == "3d":
            frame = perspective(world, (self.size * 4 // 3, self.size), world.labels)
        else:
            frame = self.top_down(world)
        if self.cameras:
            frame = np.hstack([frame, self._camera_column(world)])
        self._write(frame)

    def top_down(self, world: World) -> np.ndarray:
        """A plan view drawn from ground truth (x right, y up), BGR."""
        truth, room = world.truth, world.scenario.room
        margin = 10
        scale = (self.size - 2 * margin) / max(room.width, room.depth)
        image = np.full((self.size, self.size, 3), WALL_BGR, np.uint8)

        def px(x: float, y: float) -> tuple[int, int]:
            return (int(self.size / 2 + x * scale), int(self.size / 2 - y * scale))

        cv2.rectangle(image, px(-room.width / 2, room.depth / 2),
                      px(room.width / 2, -room.depth / 2), FLOOR_BGR, -1)
        for i in range(len(truth.tables)):
            corners = np.array([px(c[0], c[1]) for c in truth.table_corners(index=i)], np.int32)
            lift = truth.table_pose(i)[2]
            cv2.fillPoly(image, [corners], _bgr(TABLE_COLOUR, 1.0 if lift < 0.02 else 1.1))
            cv2.polylines(image, [corners], True, (0, 0, 255) if world.dropped else (255, 255, 255),
                          2 if world.dropped else 1)
        for target in world.scenario.targets:
            cv2.drawMarker(image, px(target.x, target.y), (0, 0, 200), cv2.MARKER_CROSS, 12, 2)
            cv2.putText(image, target.id, px(target.x + 0.15, target.y - 0.15), cv2.FONT_HERSHEY_SIMPLEX, 0.4,
                        (0, 0, 200), 1, cv2.LINE_AA)
        for index, name in enumerate(world.robots):
            self._draw_robot(image, world, name, ROBOT_COLOURS[index % len(ROBOT_COLOURS)], px)
        for name in world.robots:
            x, y, _ = truth.robot_pose(name)
            label(image, robot_text(name, world.labels), px(x, y + 0.3))
        status(image, world)
        if truth.tables:
            gap = max(truth.table_wall_distance(i) for i in range(len(truth.tables)))
            cv2.putText(image, f"wall gap {gap:.2f} m", (margin + 4, self.size - margin - 6),
                        cv2.FONT_HERSHEY_SIMPLEX, 0.45, (255, 255, 255), 1, cv2.LINE_AA)
        return image

    @staticmethod
    def _draw_robot(image: np.ndarray, world: World, name: str,
                    colour: tuple[float, float, float], px: object) -> None:
        assert callable(px)
        x, y, yaw = world.truth.robot_pose(name)
        c, s = math.cos(yaw), math.sin(yaw)
        if name not in world.truth.robot_bodies:  # a light body: a disc
            centre, edge = px(x, y), px(x + LIGHT_BODY.radius, y)
            cv2.circle(image, centre, max(1, edge[0] - centre[0]), _bgr(colour), -1)
            nose = px(x + c * LIGHT_BODY.radius, y + s * LIGHT_BODY.radius)
            cv2.line(image, centre, nose, _bgr(colour, 0.6), 2)
            return
        g = world.truth.robot_bodies[name].geometry
        box = [(x + c * dx - s * dy, y + s * dx + c * dy)
               for dx, dy in ((g.half_depth, g.half_width), (-g.half_depth, g.half_width),
                              (-g.half_depth, -g.half_width), (g.half_depth, -g.half_width))]
        cv2.fillPoly(image, [np.array([px(*b) for b in box], np.int32)], _bgr(colour))
        cv2.line(image, px(x, y), px(x + c * 0.25, y + s * 0.25), _bgr(colour, 0.6), 2)

    def _camera_column(self, world: World) -> np.ndarray:
        """Each robot's forward and down views stacked, scaled to the frame's height."""
        tiles = [np.hstack([robot.image("forward"), robot.image("down")])
                 for robot in world.robots.values() if isinstance(robot, Robot)]
        column = cv2.cvtColor(np.vstack(tiles), cv2.COLOR_RGB2BGR)
        width = int(column.shape[1] * self.size / column.shape[0])
        return cv2.resize(column, (width, self.size), interpolation=cv2.INTER_NEAREST)

    def _write(self, frame: np.ndarray) -> None:
        self.last = frame
        self.frames += 1
        if self._failed is None:
            try:
                self._video.write(frame)
            except (OSError, av.FFmpegError) as exc:  # a full disk: the run goes on, `close` reports it
                self._failed = f"{self.path} ({exc})"

    def close(self) -> None:
        """Finish the video and write the last frame as <path>.png; OSError naming what failed."""
        failed = [self._failed] if self._failed else []
        try:
            self._video.close()
        except (OSError, av.FFmpegError) as exc:
            failed.append(f"{self.path} ({exc})")
        if self.last is not None:
            picture = self.path.with_suffix(".png")
            try:
                written = cv2.imwrite(str(picture), self.last) and picture.stat().st_size > 0
            except (OSError, cv2.error):
                written = False
            if not written:
                failed.append(str(picture))
        if failed:
            raise OSError(f"cannot write {' and '.join(failed)}")
