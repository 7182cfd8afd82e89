"""Printing for the CLIs: findings, results, the per-behaviour time table."""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any, TextIO

from hfsm.cli import snippet
from hfsm.errors import Finding

if TYPE_CHECKING:  # `--check` prints findings without loading the interpreter
    from hfsm.runtime.agent import AgentResult, BehaviourStats
    from hfsm.runtime.run import RunResult


def findings(items: Iterable[Finding], out: TextIO | None = None) -> None:
    """Each finding's line, then its source line with a caret under what it points at."""
    out = out or sys.stderr
    colour = snippet.use_colour(out)
    source = snippet.file_lines()
    for f in items:
        print(snippet.render(f, source(f.file), colour=colour), file=out)


def json_result(result: RunResult, extra: dict[str, Any]) -> str:
    agents = {name: _entry(r) for name, r in result.agents.items()}
    body: dict[str, Any] = dict(next(iter(agents.values()))) if len(agents) == 1 else {"agents": agents}
    if result.error:
        body["error"] = result.error
    body.update(extra)
    return json.dumps(body, default=str, allow_nan=False)


def _entry(r: AgentResult) -> dict[str, Any]:
    entry = {"outcome": r.outcome, "outputs": r.outputs, "time": r.time}
    if r.failed is not None:
        entry["failed"] = r.failed
    return entry


def text_result(result: RunResult, extra: dict[str, Any] | None = None, out: TextIO | None = None) -> None:
    out = out or sys.stdout
    for name, r in result.agents.items():
        ended = f"ended in '{r.outcome}'" if r.outcome is not None else "did not end"
        if r.failed is not None:
            ended = f"failed ({r.failed})"
        outputs = f" with {json.dumps(r.outputs, default=str)}" if r.outputs else ""
        print(f"{name}: {ended} at t={r.time:g} s{outputs}", file=out)
    for key, value in (extra or {}).items():
        shown = ", ".join(f"{k} {v}" for k, v in value.items()) if isinstance(value, dict) else value
        print(f"{key}: {shown}", file=out)


def summary(stats: dict[str, dict[str, BehaviourStats]], dt: float, out: TextIO | None = None) -> None:
    """Per behaviour: calls, how they ended, total and mean time (the shape of the paper's Figure 10)."""
    rows = []
    for agent, table in stats.items():
        for behaviour, s in sorted(table.items()):
            total = s.ticks * dt
            ends = ", ".join(f"{e} {n}" for e, n in sorted(s.events.items()))
            rows.append((agent, behaviour, str(s.calls), f"{total:.2f}", f"{total / s.calls:.2f}", ends))
    if not rows:
        return
    out = out or sys.stderr
    head = ("agent", "behaviour", "calls", "total s", "mean s", "ended with")
    widths = [max(len(r[i]) for r in [head, *rows]) for i in range(len(head))]
    for row in [head, *rows]:
        cells = [
            c.rjust(w) if 2 <= i <= 4 else c.ljust(w)
            for i, (c, w) in enumerate(zip(row, widths, strict=True))
        ]
        print("  ".join(cells).rstrip(), file=out)
