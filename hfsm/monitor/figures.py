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
    """The drawings a page shows: given, or made in a thread beside the run (Graphviz takes a while
    for many machines, and a live run should not wait for it)."""

    def __init__(
        self, svgs: Mapping[str, str] | None = None, make: Callable[[], dict[str, str]] | None = None
    ) -> None:
        self.svgs: dict[str, str] = dict(svgs or {})
        self._done = threading.Event()
        if make is None:
            self._done.set()
        else:
            threading.Thread(target=self._make, args=(make,), name="hfsm-figures", daemon=True).start()

    def _make(self, make: Callable[[], dict[str, str]]) -> None:
        try:
            self.svgs = make()
        finally:
            self._done.set()

    def ready(self) -> bool:
        return self._done.is_set()
