"""DOT text -> SVG, PNG or PDF bytes, in process, through pygraphviz (whose wheel carries Graphviz)."""

from __future__ import annotations

import os
import sys
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Literal

FORMATS = ("svg", "png", "pdf", "dot")
Format = Literal["svg", "png", "pdf", "dot"]


class RenderError(Exception):
    """Graphviz could not lay out or draw a figure (a bug in the DOT we wrote, or in Graphviz)."""


def render(dot: str, fmt: str) -> bytes:
    """The figure in `fmt`: DOT text itself for 'dot', else drawn by Graphviz's `dot` layout."""
    if fmt == "dot":
        return dot.encode("utf-8")
    import pygraphviz  # a heavy import: only when drawing

    with _quiet_stderr():
        try:
            data = pygraphviz.AGraph(string=dot).draw(format=fmt, prog="dot")
        except (OSError, ValueError) as exc:  # pygraphviz reports Graphviz failures so
            raise RenderError(str(exc)) from exc
    if not data:
        raise RenderError(f"Graphviz drew an empty {fmt}")
    return bytes(data)


@contextmanager
def _quiet_stderr() -> Iterator[None]:
    """Keep the C library's chatter (fontconfig warnings) off our stderr while Graphviz runs."""
    try:
        fd = sys.stderr.fileno()
    except (AttributeError, OSError, ValueError):  # stderr replaced (pytest capture)
        yield
        return
    sys.stderr.flush()
    saved = os.dup(fd)
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), fd)
        try:
            yield
        finally:
            os.dup2(saved, fd)
            os.close(saved)
