"""Video files that play in browsers, GitHub and editors: H.264 in MP4, VP9 in WebM, or a GIF.

Written through PyAV (FFmpeg with libx264 and libvpx in its wheel): OpenCV's wheel can only write
MPEG-4 part 2 (`mp4v`), which browsers do not play. Frames are encoded as they come, never held.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import av
import numpy as np

CODECS = {".mp4": ("libx264", "yuv420p"), ".webm": ("libvpx-vp9", "yuv420p"), ".gif": ("gif", "rgb8")}
OPTIONS: dict[str, dict[str, object]] = {
    "libx264": {"preset": "veryfast", "crf": "26", "movflags": "+faststart"},
    "libvpx-vp9": {"deadline": "realtime", "cpu-used": "8", "crf": "34", "b": "0"},
    "gif": {},
}


class VideoWriter:
    """Frames (H x W x 3, BGR uint8, all of one size) into `path`, by its suffix."""

    def __init__(self, path: Path, fps: float) -> None:
        suffix = path.suffix.lower()
        if suffix not in CODECS:
            raise ValueError(f"a video is .mp4, .webm or .gif, not '{path.name}'")
        self.path, self.fps = path, fps
        self._codec, self._pix_fmt = CODECS[suffix]
        self._container: av.container.OutputContainer | None = None
        self._stream: av.video.stream.VideoStream | None = None

    def _open(self, width: int, height: int) -> av.video.stream.VideoStream:
        options = {k: str(v) for k, v in OPTIONS[self._codec].items()}
        container_options = {"movflags": options.pop("movflags")} if "movflags" in options else {}
        self._container = av.open(str(self.path), "w", options=container_options)
        stream = self._container.add_stream(self._codec, rate=Fraction(self.fps).limit_denominator(1000))
        assert isinstance(stream, av.video.stream.VideoStream)
        stream.width, stream.height = width + width % 2, height + height % 2  # yuv420p needs even sizes
        stream.pix_fmt = self._pix_fmt
        stream.options = dict(options)
        self._stream = stream
        return stream

    def write(self, frame: np.ndarray) -> None:
        height, width = frame.shape[:2]
        stream = self._stream or self._open(width, height)
        if (stream.width, stream.height) != (width, height):
            frame = np.pad(frame, ((0, stream.height - height), (0, stream.width - width), (0, 0)))
        assert self._container is not None
        for packet in stream.encode(av.VideoFrame.from_ndarray(frame, format="bgr24")):
            self._container.mux(packet)

    def close(self) -> None:
        """Flush the encoder and finish the file; a writer never written to leaves no file."""
        if self._container is None or self._stream is None:
            return
        for packet in self._stream.encode():
            self._container.mux(packet)
        self._container.close()
        self._container = self._stream = None
