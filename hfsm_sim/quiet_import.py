"""Import pybullet without its banner: it prints "pybullet build time: ..." from C on stderr when it
is first imported, a line that would show on every command (and mix with what commands say)."""

from __future__ import annotations

import contextlib
import ctypes
import os
import sys


def import_pybullet_quietly() -> None:
    if "pybullet" in sys.modules:
        return
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        import pybullet  # noqa: F401  (an import error still raises, with its message)
    finally:
        _flush_c_streams()  # what C printed may sit in its buffers: flush it into /dev/null
        for fd, copy in zip((1, 2), saved, strict=True):
            os.dup2(copy, fd)
            os.close(copy)
        os.close(devnull)


def _flush_c_streams() -> None:
    with contextlib.suppress(OSError, AttributeError):  # no C library to ask: the banner may show
        ctypes.CDLL(None).fflush(None)
