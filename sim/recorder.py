"""Top-down video of a run (MP4 'mp4v', or GIF), optionally with the robots' camera views,
and a PNG of the last frame. The world calls `capture` every `every` simulated seconds."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import cv2
import numpy as np

from sim.profile import ROBOT_COLOURS, TABLE_COLOUR

if TYPE_CHECKING:
    from sim.world import World

FLOOR_BGR, WALL_BGR = (60, 80, 105), (215, 230, 235)


def _bgr(rgb: tuple[float, float, float], shade: float = 1.0) -> tuple[int, int, int]:
    return (int(rgb[2] * 255 * shade), int(rgb[1] * 255 * shade), int(rgb[0] * 255 * shade))


class Recorder:
    def __init__(self, path: str | Path, *, every: float = 0.5, size: int = 480,
                 cameras: bool = False, fps: float = 10.0) -> None:
        self.path = Path(path)
        self.every, self.size, self.cameras, self.fps = every, size, cameras, fps
        self._writer: cv2.VideoWriter | None = None
        self._gif: list[np.ndarray] = []
        self.last: np.ndarray | None = None
        self.frames = 0

    def capture(self, world: World) -> None:
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
        corners = np.array([px(c[0], c[1]) for c in truth.table_corners()], np.int32)
        lift = truth.table_pose()[2]
        cv2.fillPoly(image, [corners], _bgr(TABLE_COLOUR, 1.0 if lift < 0.02 else 1.1))
        cv2.polylines(image, [corners], True, (0, 0, 255) if world.dropped else (255, 255, 255),
                      2 if world.dropped else 1)
        for index, name in enumerate(world.robots):
            self._draw_robot(image, world, name, ROBOT_COLOURS[index % len(ROBOT_COLOURS)], px)
        cv2.putText(image, f"t={world.time:6.1f}s  wall gap {truth.table_wall_distance():.2f} m",
                    (margin + 4, self.size - margin - 6), cv2.FONT_HERSHEY_SIMPLEX, 0.45,
                    (255, 255, 255), 1, cv2.LINE_AA)
        return image

    @staticmethod
    def _draw_robot(image: np.ndarray, world: World, name: str,
                    colour: tuple[float, float, float], px: object) -> None:
        assert callable(px)
        x, y, yaw = world.truth.robot_pose(name)
        g = world.truth.robot_bodies[name].geometry
        c, s = math.cos(yaw), math.sin(yaw)
        box = [(x + c * dx - s * dy, y + s * dx + c * dy)
               for dx, dy in ((g.half_depth, g.half_width), (-g.half_depth, g.half_width),
                              (-g.half_depth, -g.half_width), (g.half_depth, -g.half_width))]
        cv2.fillPoly(image, [np.array([px(*b) for b in box], np.int32)], _bgr(colour))
        cv2.line(image, px(x, y), px(x + c * 0.25, y + s * 0.25), _bgr(colour, 0.6), 2)
        cv2.putText(image, name, px(x + 0.15, y + 0.15), cv2.FONT_HERSHEY_SIMPLEX, 0.4,
                    (255, 255, 255), 1, cv2.LINE_AA)

    def _camera_column(self, world: World) -> np.ndarray:
        """Each robot's forward and down views stacked, scaled to the frame's height."""
        tiles = [np.hstack([world.robots[n].image("forward"), world.robots[n].image("down")])
                 for n in world.robots]
        column = cv2.cvtColor(np.vstack(tiles), cv2.COLOR_RGB2BGR)
        width = int(column.shape[1] * self.size / column.shape[0])
        return cv2.resize(column, (width, self.size), interpolation=cv2.INTER_NEAREST)

    def _write(self, frame: np.ndarray) -> None:
        self.last = frame
        self.frames += 1
        if self.path.suffix.lower() == ".gif":
            self._gif.append(frame)
            return
        if self._writer is None:
            height, width = frame.shape[:2]
            fourcc = cv2.VideoWriter.fourcc(*"mp4v")
            self._writer = cv2.VideoWriter(str(self.path), fourcc, self.fps, (width, height))
            if not self._writer.isOpened():
                self.path = self.path.with_suffix(".gif")
                self._writer = None
                self._gif.append(frame)
                return
        self._writer.write(frame)

    def close(self) -> None:
        """Finish the video and write the last frame as <path>.png; OSError when a file failed.

        OpenCV reports no write errors: a video that is missing or empty afterwards is the sign."""
        failed: list[str] = []
        if self._writer is not None:
            self._writer.release()
            self._writer = None
            if not _written(self.path):
                failed.append(str(self.path))
        if self._gif:
            animation = cv2.Animation()
            animation.frames = self._gif
            animation.durations = [int(1000 / self.fps)] * len(self._gif)
            self._gif = []
            if not _try_write(lambda: cv2.imwriteanimation(str(self.path), animation), self.path):
                failed.append(str(self.path))
        if self.last is not None:
            picture = self.path.with_suffix(".png")
            last = self.last
            if not _try_write(lambda: cv2.imwrite(str(picture), last), picture):
                failed.append(str(picture))
        if failed:
            raise OSError(f"cannot write {' and '.join(failed)} (a full disk? no permission?)")


def _written(path: Path) -> bool:
    try:
        return path.stat().st_size > 0
    except OSError:
        return False


def _try_write(write: Callable[[], bool], path: Path) -> bool:
    try:
        return bool(write()) and _written(path)
    except cv2.error:
        return False
