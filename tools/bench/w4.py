"""W4, parallel: one parallel state of four regions, each a one-tick wait, joined when all four end.

- hfsm: `p` is a parallel state whose regions are one-tick `wait`s; its one join rule needs all four
  `done` and re-enters `p`, so every tick ends four regions, takes the join and starts four again;
  the machine `timer` ends the run after n joins (as in W1).
- transitions: a `HierarchicalMachine` whose state `P` is parallel (regions r1..r4, `run -> done` on
  `tick`, `done` final); `on_final` of `P` marks the join, and `join` re-enters `P`.
- sismic: a parallel state `P` (orthogonal regions r1..r4, `run -> done` on `tick`, `done` final) with
  an eventless transition back to `P` guarded by `active()` of the four `done` states.
A unit is one join: four region ends, the join, and the re-entry of the state and its regions.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from bench.harness import Workload, expect

REGIONS = 4

_HFSM_REGIONS = "\n".join(f"      r{i}: {{do: wait, with: {{seconds: 0.05}}}}" for i in range(1, REGIONS + 1))
_HFSM_WHEN = ", ".join(f"r{i}: done" for i in range(1, REGIONS + 1))
HFSM = f"""\
doc: bench_engine W4, parallel. Four one-tick waits in one parallel state, joined when all end.
params:
  limit: {{type: float, default: 1.0}}
outcomes: [timeout]
timer: "${{params.limit}}"
states:
  p:
    parallel:
{_HFSM_REGIONS}
    join:
      - when: {{{_HFSM_WHEN}}}
        then: p
"""


@dataclass
class Joins:
    """Peers' side: machines and how to take one join on each."""

    machines: list[Any] = field(default_factory=list)
    steps: list[Callable[[], None]] = field(default_factory=list)
    joins: list[Callable[[], int]] = field(default_factory=list)
    per_machine: int = 0


class _TransitionsModel:
    def __init__(self) -> None:
        self.joined = False
        self.joins = 0

    def all_done(self) -> None:
        self.joined = True


def _transitions(n: int) -> Joins:
    from transitions.extensions import HierarchicalMachine

    regions = [
        {
            "name": f"r{i}",
            "initial": "run",
            "children": ["run", {"name": "done", "final": True}],
            "transitions": [["tick", "run", "done"]],
        }
        for i in range(1, REGIONS + 1)
    ]
    model = _TransitionsModel()
    HierarchicalMachine(
        model=model,
        states=[{"name": "P", "parallel": regions, "on_final": "all_done"}],
        initial="P",
        transitions=[["join", "P", "P"]],
    )

    def step() -> None:
        model.tick()  # type: ignore[attr-defined]
        if model.joined:
            model.joined = False
            model.join()  # type: ignore[attr-defined]
            model.joins += 1

    return Joins([model], [step], [lambda: model.joins], n)


_SISMIC_REGIONS = "\n".join(
    f"      - name: r{i}\n        initial: r{i}_run\n        states:\n        - name: r{i}_run\n"
    f"          transitions:\n          - target: r{i}_done\n            event: tick\n"
    f"        - name: r{i}_done\n          type: final"
    for i in range(1, REGIONS + 1)
)
_SISMIC_GUARD = " and ".join(f"active('r{i}_done')" for i in range(1, REGIONS + 1))
SISMIC = f"""\
statechart:
  name: bench_w4
  root state:
    name: root
    initial: P
    states:
    - name: P
      parallel states:
{_SISMIC_REGIONS}
      transitions:
      - target: P
        guard: {_SISMIC_GUARD}
"""


def _sismic(n: int) -> Joins:
    from sismic.interpreter import Interpreter
    from sismic.io import import_from_yaml

    interpreter = Interpreter(import_from_yaml(SISMIC))
    interpreter.execute()
    joins = [0]

    def step() -> None:
        interpreter.queue("tick")
        steps = interpreter.execute()
        expect(len(steps) == 2, f"sismic W4: {len(steps)} steps for a tick, expected 2 (tick, join)")
        joins[0] += 1

    return Joins([interpreter], [step], [lambda: joins[0]], n)


PEERS: dict[str, Callable[[int], Joins]] = {"transitions": _transitions, "sismic": _sismic}


def peer_workload(lib: str, n: int) -> Workload[Joins]:
    def execute(j: Joins) -> None:
        for step in j.steps:
            for _ in range(j.per_machine):
                step()

    def check(j: Joins, n: int) -> None:
        got = [count() for count in j.joins]
        expect(got == [j.per_machine] * len(j.joins), f"{lib} W4: joins {got}, expected {j.per_machine} each")

    return Workload(PEERS[lib], execute, check, n, calibrate=200)
