"""Each machine a run can reach, drawn as SVG by hfsm-graph's own renderer, for the page to light."""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable, Mapping

from hfsm.diagram.dot import to_dot
from hfsm.diagram.extract import Sources, machine_figure
from hfsm.diagram.render import RenderError, render
from hfsm.load import Loaded
from hfsm.registry import Registry


def machine_svgs(loaded: Loaded, registry: Registry, names: Iterable[str] | None = None) -> dict[str, str]:
    """name -> SVG text of every loaded machine (or of `names`); a machine Graphviz fails on is left
    out, and the page shows its path without a drawing."""
    src = Sources.from_loaded(loaded, registry)
    chosen = sorted(names if names is not None else loaded.machines)
    svgs: dict[str, str] = {}
    for name in chosen:
        try:
            dot = to_dot(machine_figure(name, src, 0, chosen), "svg")
            svgs[name] = render(dot, "svg").decode("utf-8")
        except RenderError:
            continue
    return svgs


class Figures:
    """The drawings a page shows: given, or made in a thread when a page first asks for them (Graphviz
    takes a while for many machines: a live run neither waits for it nor pays for it unwatched)."""

    def __init__(
        self, svgs: Mapping[str, str] | None = None, make: Callable[[], dict[str, str]] | None = None
    ) -> None:
        self.svgs: dict[str, str] = dict(svgs or {})
        self._make = make
        self._done = threading.Event()
        self._lock = threading.Lock()
        if make is None:
            self._done.set()

    def ready(self) -> bool:
        """Whether the drawings are made; the first call starts making them."""
        with self._lock:
            make, self._make = self._make, None
        if make is not None:
            threading.Thread(target=self._run, args=(make,), name="hfsm-figures", daemon=True).start()
        return self._done.is_set()

    def _run(self, make: Callable[[], dict[str, str]]) -> None:
        try:
            self.svgs = make()
        finally:
            self._done.set()
