"""One seeded run of a machine in the simulator, as plain data: for benchmarks and reproduction."""

from __future__ import annotations

import contextlib
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.program import Program, machine_params
from hfsm.runtime.run import RunOptions, run
from hfsm.trace import JsonlTrace, TraceSink
from hfsm_behaviours.simworld import SimWorld, load_scenario
from hfsm_sim import World


@dataclass(frozen=True)
class TrialSpec:
    machine: str
    scenario: str
    seed: int
    params: dict[str, Any] = field(default_factory=dict)
    max_time: float = 2400.0
    dt: float = 0.05
    trace: str | None = None
    video: str | None = None
    radio_latency: float = 0.1
    radio_loss: float = 0.0
    image_size: tuple[int, int] = (160, 120)
    renderer: str = "raster"  # or "tiny": pybullet's, to compare with


@dataclass
class TrialResult:
    spec: TrialSpec
    outcomes: dict[str, str | None]
    time: float
    error: str | None
    score: dict[str, Any]
    seconds: dict[str, dict[str, float]]  # agent -> behaviour -> total simulated seconds
    calls: dict[str, dict[str, int]]
    wall: float

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def run_trial(spec: TrialSpec, sink: TraceSink | None = None) -> TrialResult:
    """Load, check and run `spec.machine` for the scenario's robots; never raises for a failed run.
    The trace goes to the file `spec.trace` or, without one, to `sink` (a scorer's own reader)."""
    started = time.perf_counter()
    registry = Registry.discover()
    loaded = load([Path(spec.machine)], registry=registry)
    top = loaded.roots[0]
    params = machine_params(top, spec.params)
    scenario, _ = load_scenario(spec.scenario)
    with contextlib.ExitStack() as stack:
        world = SimWorld(World(scenario, spec.seed, radio_latency=spec.radio_latency,
                               radio_loss=spec.radio_loss, recorder=_recorder(spec.video),
                               image_size=spec.image_size, renderer=spec.renderer))
        stack.callback(world.close)
        trace = JsonlTrace(Path(spec.trace)) if spec.trace else sink
        if trace:
            stack.callback(trace.close)
        options = RunOptions(top.name, world.agent_names(), params, spec.seed, spec.max_time)
        result = run(Program(loaded.machines, registry, spec.dt), world, options, trace)
        score = world.report()["score"]
    seconds = {a: {b: s.ticks * spec.dt for b, s in t.items()} for a, t in result.stats.items()}
    calls = {a: {b: s.calls for b, s in t.items()} for a, t in result.stats.items()}
    outcomes = {a: r.outcome for a, r in result.agents.items()}
    wall = time.perf_counter() - started
    return TrialResult(spec, outcomes, result.time, result.error, score, seconds, calls, wall)


def run_trial_dict(spec: TrialSpec) -> dict[str, Any]:
    """`run_trial` as plain data, its prints sent to stderr: what sweep workers run."""
    from hfsm.cli.quiet import stdout_to_stderr

    with stdout_to_stderr():
        return run_trial(spec).as_dict()


def _recorder(video: str | None) -> Any:
    if not video:
        return None
    from hfsm_sim.recorder import Recorder

    Path(video).parent.mkdir(parents=True, exist_ok=True)
    return Recorder(video)
