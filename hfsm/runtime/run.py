"""The run loop: all agents in lockstep on one clock, until each ends, an error, or the time limit."""

from __future__ import annotations

import queue
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from hfsm.autonomy import FULL, Decision
from hfsm.runtime.agent import Agent, AgentResult, BehaviourStats, Frame
from hfsm.runtime.breaks import Breakpoint, Breaks
from hfsm.runtime.engine import Engine, FatalError
from hfsm.runtime.failing import Failure, Failures, all_failed
from hfsm.runtime.holds import hold_text
from hfsm.runtime.operator import Operator
from hfsm.runtime.program import Program, RMachine, span_ticks
from hfsm.runtime.scopes import run_under
from hfsm.trace import TraceSink
from hfsm.world import World


@dataclass
class RunResult:
    agents: dict[str, AgentResult]
    time: float
    error: str | None = None
    traceback: str = ""
    stats: dict[str, dict[str, BehaviourStats]] = field(default_factory=dict)
    error_agent: str = ""  # who met the error, and the path of the state where (when known)
    error_origin: str = ""
    error_where: tuple[str | int, ...] = ()  # the failed expression's path in its machine file, when known

    @property
    def exit_code(self) -> int:
        return 1 if self.error else 0


@dataclass
class RunOptions:
    top: str
    agents: Sequence[str]
    params: dict[str, Any]
    seed: int = 0
    max_time: float = 3600.0
    failures: Sequence[Failure] = ()
    agent_params: Mapping[str, dict[str, Any]] = field(default_factory=dict)  # an agent's own params
    autonomy: int = FULL  # the run's level at the start
    decisions: Sequence[Decision] = ()  # the operator's, from a script or a trace
    live: queue.Queue[Decision] | None = None  # the operator's, as a live page sends them
    breaks: list[Breakpoint] = field(default_factory=list)  # records that pause the run (shared: a page adds)
    scopes: Mapping[str, tuple[str, tuple[str, ...]]] = field(default_factory=dict)  # agent -> scope


def run(program: Program, world: World, options: RunOptions, trace: TraceSink | None = None) -> RunResult:
    agents = [Agent(n, options.top, None, options.seed, world) for n in options.agents]
    world.start([a.name for a in agents], program.dt)
    for agent in agents:
        agent.robot = world.handle(agent.name)
    breaks = Breaks(options.breaks, trace) if options.breaks or options.live is not None else None
    engine = Engine(agents, world, program.dt, breaks or trace)
    engine.level = options.autonomy
    engine.breaks = breaks
    if options.scopes:
        run_under(agents, options.scopes)
    try:
        error, tb, fatal = _loop(engine, program, options, world)
        if error:
            _stop_all(engine, agents)
    finally:
        if engine.records is not None:
            engine.records.drain()
    if not error and all_failed(agents):
        error = "every agent failed"
    results = {a.name: a.result or AgentResult(None, {}, engine.time) for a in agents}
    stats = {a.name: a.stats for a in agents}
    who, origin, where = (fatal.agent, fatal.origin, fatal.where) if fatal is not None else ("", "", ())
    return RunResult(results, engine.time, error, tb, stats, who, origin, where)


def _loop(
    engine: Engine, program: Program, options: RunOptions, world: World
) -> tuple[str | None, str, FatalError | None]:
    agents = engine.agents
    last = span_ticks(options.max_time, program.dt)
    top = program.machines[options.top]
    failures = Failures(engine, options.failures)
    operator = Operator(engine, options.decisions, options.live)
    world_records = getattr(world, "trace_records", None)  # a world may add records (robots' poses)
    try:
        paused = _begin(engine, operator, failures, top, options)
        if paused:
            return "blocked forever: " + paused, "", None
        while engine.running:
            following = _following(engine, failures, operator)
            if following is None or following > last:
                return _stopped(engine, following, last, options.max_time), "", None
            if not world.static:
                world.advance(engine.tick)
                _world_records(engine, world_records, following)
            engine.tick = following
            if operator.busy and (paused := _operator_first(operator, following)):
                return "blocked forever: " + paused + "; " + _where(engine.agents), "", None
            if failures.due or not world.static:
                failures.apply(following)
            arrived = world.collect(following)
            if arrived:
                engine.deliver(arrived)
            for agent in agents:
                if agent.result is None:
                    agent.entries = 0
                    engine.step(agent.root)  # type: ignore[arg-type]
            if engine.records is not None:
                engine.records.flush()
    except FatalError as exc:
        return exc.args[0], exc.traceback, exc
    return None, "", None


def _following(engine: Engine, failures: Failures, operator: Operator) -> int | None:
    """The next tick to run: the next (a static world: the next in which anything can happen); while
    paused, the next, whatever is due in it, since a step runs one tick."""
    if operator.paused or not engine.world.static:
        return engine.tick + 1
    return _next_tick(engine, failures, operator if operator.busy else None)


def _begin(engine: Engine, operator: Operator, failures: Failures, top: RMachine, options: RunOptions) -> str:
    """Tick 0: the operator's decisions, failures, every agent's start; why it can never go on, or ''."""
    paused = _operator_first(operator, 0)
    if not paused:
        failures.apply(0)
        _start(engine, top, options)
    return paused


def _operator_first(operator: Operator, tick: int) -> str:
    """The operator's decisions due at the start of `tick`; while paused, those that come until one
    resumes or steps the run. Why the run can never go on, or ''."""
    operator.ran()
    operator.apply(tick)
    return operator.hold_on(tick) if operator.paused else ""


def _start(engine: Engine, top: RMachine, options: RunOptions) -> None:
    """Every agent not failed at 0 s starts its top machine (tick 0, whose records the sink gets with
    the next tick's)."""
    for agent in engine.agents:
        if agent.result is None:
            agent.entries = 0
            engine.start(agent, top, options.agent_params.get(agent.name, options.params))
    if engine.records is not None:
        engine.records.drain()


def _stopped(engine: Engine, following: int | None, last: int, max_time: float) -> str:
    """Why a run stops before every agent ended: nothing can happen any more, or --max-time."""
    if following is None:
        holds = "; ".join(filter(None, (hold_text(a) for a in engine.agents)))
        return "blocked forever: " + _where(engine.agents) + (f"; held: {holds}" if holds else "")
    engine.tick = max(engine.tick, last)
    return f"stopped at --max-time {max_time:g} s: " + _where(engine.agents)


WorldRecords = Callable[[int], list[dict[str, Any]]]


def _world_records(engine: Engine, records: WorldRecords | None, tick: int) -> None:
    if records is not None and engine.records is not None:
        for record in records(tick):
            engine.records.put(record)


def _next_tick(engine: Engine, failures: Failures, operator: Operator | None = None) -> int | None:
    """In a static world, the next tick in which anything can happen; None when nothing can."""
    now = engine.tick
    hit = operator is not None and operator.hit()
    if engine.wake or (engine.team.waiting and engine.team.live()) or hit:
        engine.wake = False
        return now + 1
    best = engine.world.next_delivery() or sys.maxsize
    for agent in engine.agents:
        if agent.result is not None or agent.root is None:
            continue
        root = agent.root
        below = root.below
        if below.__class__ is Frame or below.__class__ is list or below is None or root.state.timed \
                or root.held is not None:
            best = _wake(root, now, best)
        else:  # one machine running one behaviour: the common case, without a call
            for deadline in (root.deadline, root.state_deadline, root.retry_at, below.deadline):
                if deadline is not None and now < deadline < best:
                    best = deadline
        if best == now + 1:
            break
    decided = operator.next_due() if operator is not None else None
    if decided is not None and decided < best:
        best = max(decided, now + 1)  # the operator may answer what waits
    if best == sys.maxsize:
        if operator is not None and operator.live is not None:
            operator.wait_live()  # nothing else can happen: the live operator's answer comes next
            return now + 1
        return None  # a failure to come is no agent advancing: blocked forever now
    if failures.due:
        best = min(best, failures.due[0][0])
    return best


def _wake(frame: Frame, now: int, best: int) -> int:
    """The earliest tick after `now`, and before `best`, in which something at or below `frame` is due."""
    while True:
        if frame.state.timed and frame.held is None:
            return now + 1
        for deadline in (frame.deadline, frame.state_deadline, frame.retry_at):
            if deadline is not None and now < deadline < best:
                best = deadline
        below = frame.below
        if below is None:
            return best
        cls = below.__class__
        if cls is Frame:
            frame = below
            continue
        if cls is list:
            for region in below:
                inner = region.below
                if inner.__class__ is Frame:
                    best = _wake(inner, now, best)
                elif inner is not None and now < (inner.deadline or 0) < best:
                    best = inner.deadline
            return best
        deadline = below.deadline
        return deadline if deadline is not None and now < deadline < best else best


def _where(agents: list[Agent]) -> str:
    return "; ".join(f"{a.name} in {a.where()}" for a in agents if a.result is None and a.root is not None)


def _stop_all(engine: Engine, agents: list[Agent]) -> None:
    """Cancel what still runs, so that every `enter` in the trace has its `exit`."""
    for agent in agents:
        if agent.result is None:
            engine.stop(agent)
