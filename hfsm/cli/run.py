"""`hfsm-run`: check a machine file and run it (docs/REFERENCE.md#hfsm-run)."""

from __future__ import annotations

import argparse
import logging
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from hfsm import plugins
from hfsm.autonomy import Decision, level_of
from hfsm.cli import guard, operating, report, resume
from hfsm.cli.fail import check_failures, fail_arg
from hfsm.cli.history import top_params
from hfsm.cli.named import machine_path
from hfsm.cli.newplugin import new_plugin, schema_hint
from hfsm.cli.operator_file import read_decisions
from hfsm.cli.quiet import stdout_to_stderr
from hfsm.errors import UsageError, UserError
from hfsm.load import Loaded, load, worlds_needed
from hfsm.monitor import live
from hfsm.names import is_name
from hfsm.registry import Registry
from hfsm.world import WORLDS_GROUP, NullWorld, World, WorldFactory

if TYPE_CHECKING:
    from hfsm.runtime.run import RunResult


def _factories() -> dict[str, WorldFactory]:
    found: dict[str, WorldFactory] = {}
    with stdout_to_stderr():
        for ep, cls in plugins.load_each(WORLDS_GROUP, lambda ep, obj: None):
            ok, factory = plugins.run_hook(ep, cls)
            if ok:
                found[factory.name] = factory
    return found


def build_parser(factories: dict[str, WorldFactory]) -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="hfsm-run", description="Check a machine file and run it.")
    p.add_argument("file", nargs="?", type=Path, help="the top machine file")
    p.add_argument(
        "--lib", action="append", type=Path, default=[], metavar="DIR", help="more machine folders"
    )
    p.add_argument("--world", choices=["none", *factories], help="default: sim if a primitive needs it")
    p.add_argument("--agents", help="comma-separated agent names (default: the world's, else 'robot')")
    p.add_argument("--param", action="append", default=[], metavar="K=V", help="a param of the top machine")
    p.add_argument(
        "--history",
        type=Path,
        metavar="FILE",
        help="the top machine's 'history' param: the team's history, read at the start (none yet if "
        "FILE is missing) and written at the end",
    )
    p.add_argument("--seed", type=guard.SEED, default=0)
    p.add_argument("--dt", type=guard.DT, default=0.05, help="seconds per tick, 0.001..10 (default 0.05)")
    p.add_argument("--max-time", type=guard.MAX_TIME, default=3600.0, metavar="S", help="default 3600")
    p.add_argument("--trace", type=Path, metavar="FILE.jsonl", help="write the trace, as the run goes")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    p.add_argument("--replay", type=Path, metavar="CE.jsonl", help="run a counterexample of hfsm-verify")
    p.add_argument("--check", action="store_true", help="validate and exit")
    p.add_argument("--strict", action="store_true", help="warnings are errors")
    p.add_argument("--schema", action="store_true", help="print the JSON Schema of machine files")
    p.add_argument("--list", nargs="?", const="", metavar="PATTERN",
                   help="print every behaviour a run can call (Markdown), or those whose name or world "
                   "matches PATTERN; with FILE, the machines beside it too")
    p.add_argument("--new-plugin", type=Path, metavar="DIR",
                   help="write a plug-in package to start from in DIR (a primitive, a machine, entry points)")
    p.add_argument("--traceback", action="store_true", help="show Python tracebacks of run-time errors")
    p.add_argument("--quiet", action="store_true", help="no summary table on stderr")
    p.add_argument("--fail-exit", action="store_true",
                   help="exit 3 when the top machine ends in one of its failures (timeout included)")
    p.add_argument(
        "--fail",
        action="append",
        type=fail_arg,
        default=[],
        metavar="AGENT@S",
        help="fail that agent S seconds into the run (repeatable)",
    )
    operating.add_arguments(p)
    for factory in factories.values():
        factory.add_arguments(p.add_argument_group(f"--world {factory.name}"))
    live.add_arguments(p)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    factories = _factories()
    try:
        parser = build_parser(factories)
        args = parser.parse_args(argv)
    except SystemExit as exit_:  # a bad flag (2, usage printed) or --help (0): a code, for callers in process
        return exit_.code if isinstance(exit_.code, int) else 2
    logging.basicConfig(level=logging.INFO, format="%(message)s", stream=sys.stderr)
    try:
        resume.prepare(args, parser, sys.argv[1:] if argv is None else argv)
        with guard.signals_raise():
            return _main(args, factories)
    except (UserError, UsageError) as err:
        if isinstance(err, UserError):
            report.findings(err.findings)
        else:
            print(f"hfsm-run: {err}", file=sys.stderr)
        return 2
    except guard.OutputError as err:
        print(f"hfsm-run: {err}", file=sys.stderr)
        return 1
    except KeyboardInterrupt as stop:
        flag = guard.StopFlag(stop.args[0] if stop.args else None)
        print(f"hfsm-run: stopped by {flag.name}", file=sys.stderr)
        return flag.exit_code


def _main(args: argparse.Namespace, factories: dict[str, WorldFactory]) -> int:
    if args.schema:
        from hfsm.schema import schema_text

        sys.stdout.write(schema_text())
        print(schema_hint(), file=sys.stderr)
        return 0
    if args.new_plugin is not None:
        return new_plugin(args.new_plugin)
    if args.list is not None:
        return _list(args)
    if args.file is None:
        raise UsageError("give a machine file or name (or --list, --schema, --new-plugin DIR)")
    with stdout_to_stderr():
        registry = Registry.discover()
    if args.world is not None and not args.replay:  # a replay stands in every primitive, as hfsm-verify
        registry = registry.for_world(args.world)
    args.file = machine_path(args.file, args.lib, registry)
    inputs = {"none": NullWorld().inputs(), **{n: f.inputs() for n, f in factories.items()}}
    loaded = load(
        [args.file],
        libs=args.lib,
        registry=registry,
        strict=args.strict,
        world=args.world,
        world_inputs=None if args.replay else inputs,  # a replay's inputs are its schedule's
    )
    report.findings(loaded.warnings)
    top = loaded.roots[0]
    world_inputs = lambda: inputs[_world_name(args, loaded, registry)]  # noqa: E731
    args.breaks = operating.conditions(args.breaks, loaded, world_inputs)
    args.edited = resume.edited(args.resumed, loaded) if args.resumed else []
    if args.check:
        if args.param or args.history:  # the params given are checked too
            top_params(args.param, args.history, top, registry)
        name = _world_name(args, loaded, registry)
        check = getattr(factories.get(name), "check", None)  # a world's own flags, if it checks them
        if check is not None:
            with stdout_to_stderr():
                check(args)
        print(f"{args.file}: ok ({len(loaded.machines)} machines checked)", file=sys.stderr)
        return 0
    if args.replay:
        from hfsm.cli.replay import replayed

        return replayed(args, loaded, registry)
    params = top_params(args.param, args.history, top, registry)
    world = _world(args, loaded, registry, factories)
    started = False
    try:
        agents = _agents(args, world)
        check_failures(args.fail, agents)
        decisions = read_decisions(args.operator, agents) if args.operator else []
        if args.resumed:  # the trace's decisions up to T, then the script's after it
            decisions = args.resumed.decisions + [d for d in decisions if d.t > args.resumed.at]
        trace_path = args.trace or world.default_trace
        outputs = [("--trace", trace_path)] if trace_path else []
        outputs += [("--video", Path(p)) for p in getattr(world, "outputs", ())]
        guard.check_outputs(outputs, _inputs(args, loaded))
        started = True
        code = _run(args, loaded, registry, world, params, agents, trace_path, decisions)
    finally:
        files = guard.close_world(world)
        for path in files if started else ():
            print(f"wrote {path}", file=sys.stderr)
    live.finish(args)  # after the world wrote its video: the page of a live run shows it
    return code


def _list(args: argparse.Namespace) -> int:
    from hfsm.cli.list import render

    with stdout_to_stderr():
        registry = Registry.discover()
    if args.world is not None:
        registry = registry.for_world(args.world)
    beside = [args.file.parent] if args.file is not None and args.file.is_file() else []
    sys.stdout.write(render(registry, [*beside, *args.lib, *registry.machine_folders], args.list))
    return 0


def _inputs(args: argparse.Namespace, loaded: Loaded) -> list[Path]:
    scenario = getattr(args, "scenario", None)
    extra = [Path(scenario)] if isinstance(scenario, str) and Path(scenario).is_file() else []
    return [mf.path for mf in loaded.machines.values()] + extra


def _world(
    args: argparse.Namespace, loaded: Loaded, registry: Registry, factories: dict[str, WorldFactory]
) -> World:
    name = _world_name(args, loaded, registry)
    if name == "none":
        return NullWorld()
    with stdout_to_stderr():
        return factories[name].create(args, args.seed)


def _world_name(args: argparse.Namespace, loaded: Loaded, registry: Registry) -> str:
    needs = worlds_needed(loaded.machines, registry)
    name: str = args.world or (needs[0] if needs else "none")
    wrong = [w for w in needs if w != name]
    if wrong:
        raise UsageError(f"these machines call primitives of --world {wrong[0]}, not --world {name}")
    return name


def _agents(args: argparse.Namespace, world: World) -> list[str]:
    named = world.agent_names()
    if args.agents is None:
        return list(named) if named else ["robot"]
    agents = [a.strip() for a in args.agents.split(",")]
    bad = [a for a in agents if not is_name(a)]
    if bad or len(set(agents)) != len(agents):
        raise UsageError(f"--agents {args.agents!r}: distinct names matching ^[a-z][a-z0-9_]*$")
    if named and list(named) != agents:
        raise UsageError(f"--agents: this world's agents are {','.join(named)}")
    return agents


def _run(
    args: argparse.Namespace,
    loaded: Loaded,
    registry: Registry,
    world: World,
    params: dict[str, object],
    agents: list[str],
    trace_path: Path | None,
    decisions: list[Decision],
) -> int:
    from hfsm.cli.stop import stoppable  # not needed to check: loaded only to run
    from hfsm.cli.tracefile import TraceFile
    from hfsm.runtime.program import Program
    from hfsm.runtime.run import RunOptions, run

    options = RunOptions(loaded.roots[0].name, agents, params, args.seed, args.max_time, args.fail,
                         autonomy=level_of(args.autonomy), decisions=decisions, breaks=args.breaks)
    args.agent_names = agents
    program = Program(loaded.machines, registry, args.dt)
    trace = TraceFile(trace_path) if trace_path else None
    checked = resume.begin(trace, args, loaded, program.dt)
    sink, monitor = live.sinks(args, checked, loaded, registry, loaded.roots[0].name, world)
    options.pace = live.pacer(args)
    if monitor is not None and monitor.control is not None:
        options.live = monitor.control.queue
        options.every_tick = args.realtime is not None  # paced: a person acts, in the very next tick
    stop = guard.StopFlag()
    try:
        with guard.signals_flag(stop):
            result = run(program, stoppable(world, stop), options, sink)
        resume.end(checked, result)
    finally:
        if sink:
            sink.close()
    args.live_monitor = monitor
    if trace and trace.failed and not result.error:
        result.error = trace.failed
    extra = world.report()
    if args.json:
        print(report.json_result(result, extra))
    else:
        report.text_result(result, extra)
    if not args.quiet:
        report.summary(result.stats, args.dt)
    if result.error:
        _print_error(result, loaded)
        if args.traceback and result.traceback:
            print(result.traceback, file=sys.stderr, end="")
    if trace and not trace.failed:
        print(f"wrote {trace_path}", file=sys.stderr)
    if stop.signum:
        return stop.exit_code
    failed = _failure_ends(result, loaded) if args.fail_exit and not result.error else []
    for agent, outcome in failed:
        print(f"hfsm-run: {agent} ended in the failure outcome '{outcome}' (--fail-exit: exit 3)",
              file=sys.stderr)
    return 3 if failed else result.exit_code


def _failure_ends(result: RunResult, loaded: Loaded) -> list[tuple[str, str]]:
    """The agents whose top machine ended in one of its failure outcomes, with the outcome."""
    failures = loaded.roots[0].model.failure_outcomes
    return [(name, end.outcome) for name, end in result.agents.items() if end.outcome in failures]


def _print_error(result: RunResult, loaded: Loaded) -> None:
    """The run's error, at the file, line and column of the state (or expression) it happened in."""
    from hfsm.cli.runerror import locate

    found = None
    if result.error_origin and result.error:
        top = loaded.roots[0].name
        found = locate(
            loaded.machines,
            top,
            result.error_origin,
            result.error,
            result.error_agent,
            result.time,
            result.error_where,
        )
    if found is None:
        print(f"error: {result.error}", file=sys.stderr)
    else:
        report.findings([found])


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
