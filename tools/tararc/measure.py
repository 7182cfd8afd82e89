"""What the bench reads of a TARARC run: a trace sink keeping the few records it scores, and the
times the paper plots (grouped, enclosed, recovered) worked out from them."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

# The states of machines/tararc*.yaml whose exits time the paper's phases.
FORMED = ("form_up", "meet_formed")
ENCLOSED = ("there", "meet_enclosed")
TIMED = {*FORMED, *ENCLOSED, "assign"}


@dataclass
class Timeline:
    """A trace sink (hfsm.trace.TraceSink) that keeps exits of the timed states, failures, and the
    team's first plan and final outcomes from the vars of the events that set them."""

    exits: list[tuple[float, str, str]] = field(default_factory=list)
    failed: dict[str, float] = field(default_factory=dict)
    first: dict[str, Any] = field(default_factory=dict)
    outcomes: dict[str, list[bool]] = field(default_factory=dict)

    def write(self, record: dict[str, Any]) -> None:
        kind = record["kind"]
        if kind == "exit":
            path = record["path"]
            if path and path[-1] in TIMED:
                self.exits.append((record["t"], record["agent"], path[-1]))
        elif kind == "failed":
            self.failed.setdefault(record["agent"], record["t"])
        elif kind == "event" and len(record["path"]) == 2:
            state, values = record["path"][1], record.get("vars", {})
            if state == "allocate" and not self.first:
                self.first = values.get("first", {})
            elif state == "remember":
                self.outcomes[record["agent"]] = list(values.get("outcomes", []))

    def flush(self) -> None:
        pass

    def close(self) -> None:
        pass


def _first_per_agent(exits: list[tuple[float, str, str]], states: tuple[str, ...], after: float = -1.0,
                     last: bool = False) -> dict[str, float]:
    """Each agent's first (or last) exit time of any of `states`, after `after`."""
    out: dict[str, float] = {}
    for t, agent, state in exits:
        if state in states and t > after and (last or agent not in out):
            out[agent] = t
    return out


def measure(line: Timeline, robots: list[str], error: str | None) -> dict[str, Any]:
    """The run's times in simulated seconds (inf when never reached) and whether every task was
    enclosed. `grouped`: every robot formed up around its agent (the paper's Figure 3 state);
    `enclosed`: every task enclosed by its group; `converge` = enclosed - grouped (Table 1, Figures
    5 and 7); `recovered`: after the first failure, every robot left working on the new plan."""
    alive = [r for r in robots if r not in line.failed]
    formed = _first_per_agent(line.exits, FORMED)
    enclosed = _first_per_agent(line.exits, ENCLOSED, last=True)
    said = [line.outcomes[r] for r in alive if r in line.outcomes]
    done = error is None and bool(said) and all(said[0]) and all(o == said[0] for o in said)
    grouped = max((formed.get(r, math.inf) for r in robots if r not in line.failed or r in formed),
                  default=math.inf)
    finish = max((enclosed.get(r, math.inf) for r in alive), default=math.inf) if done else math.inf
    out: dict[str, Any] = {
        "completed": done,
        "grouped": grouped,
        "enclosed": finish,
        "converge": finish - grouped if math.isfinite(finish) and math.isfinite(grouped) else math.inf,
        "failed": dict(sorted(line.failed.items())),
    }
    if line.failed:
        t_fail = min(line.failed.values())
        replanned = _first_per_agent(line.exits, ("assign",), after=t_fail)
        back = max((replanned.get(r, math.inf) for r in alive), default=math.inf)
        out["recovery"] = back - t_fail
    return out
