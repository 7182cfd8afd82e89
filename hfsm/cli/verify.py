"""`hfsm-verify`: explore every run the world's choices allow; a violation's shortest run found is
written as a counterexample that `hfsm-run --replay` reproduces."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hfsm.cli import report
from hfsm.cli.history import top_params
from hfsm.cli.named import machine_path
from hfsm.cli.quiet import stdout_to_stderr
from hfsm.cli.run import _factories
from hfsm.errors import Finding, Severity, UsageError, UserError
from hfsm.library import MachineFile
from hfsm.load import load
from hfsm.names import did_you_mean, is_name
from hfsm.registry import Registry
from hfsm.runtime.program import span_ticks

SHOWN = 30  # choices listed on stderr


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="hfsm-verify", description="Explore every run of a machine or a team.")
    p.add_argument("file", type=Path, help="the top machine file")
    p.add_argument(
        "--lib", action="append", type=Path, default=[], metavar="DIR", help="more machine folders"
    )
    p.add_argument("--agents", default="robot", help="comma-separated agent names (default: robot)")
    p.add_argument("--param", action="append", default=[], metavar="K=V", help="a param of the top machine")
    p.add_argument(
        "--agent-param", action="append", default=[], metavar="AGENT:K=V", help="a param for one agent"
    )
    p.add_argument(
        "--scope",
        action="append",
        default=[],
        metavar="NAME:AGENT,AGENT",
        help="the agents listed run their top machine under scope NAME (as hfsm-test's scopes:)",
    )
    p.add_argument("--loss", type=_count, default=0, metavar="N", help="messages or notices a run may lose")
    p.add_argument("--delay", type=_count, default=0, metavar="K", help="ticks each may come late")
    p.add_argument("--fail", type=_count, default=0, metavar="N", help="agents that may fail, at any tick")
    p.add_argument(
        "--bound",
        type=_seconds,
        metavar="S",
        help="run time explored (default: the top machine's timer with the params, else 600)",
    )
    p.add_argument("--max-states", type=_count, default=1_000_000, metavar="N", help="stop after N states")
    p.add_argument("--max-seconds", type=_seconds, metavar="S", help="stop after S seconds of search")
    p.add_argument(
        "--workers", type=_workers, default=1, metavar="N",
        help="processes that run the states' ticks (default 1; the same verdict and counterexample)",
    )
    p.add_argument(
        "--keys",
        choices=("bytes", "values"),
        default="bytes",
        help="a state's key: its copy's bytes (default), or its values with times relative (merges more)",
    )
    p.add_argument("--goal", choices=["success"], help="every agent that does not fail ends in no failure")
    p.add_argument("--props", type=Path, metavar="FILE", help="properties to prove (docs/VERIFY.md)")
    p.add_argument(
        "--stand-in", action="append", default=[], metavar="NAME", help="a machine to stand in for"
    )
    p.add_argument("--values", type=Path, metavar="FILE", help="stand-ins' outputs and inputs' values")
    p.add_argument("--dt", type=_seconds, default=0.05, help="seconds per tick (default 0.05)")
    p.add_argument("--seed", type=_count, default=0)
    p.add_argument(
        "--out", type=Path, metavar="CE.jsonl", help="the counterexample (default: FILE.ce.jsonl beside FILE)"
    )
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    return p


def _workers(text: str) -> int:
    value = _count(text) if text.isdigit() else 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r}: a whole number >= 1")
    return value


def _count(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text!r}: a whole number >= 0")
    return value


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not 0 < value < 1e7:
        raise argparse.ArgumentTypeError(f"{text!r}: a number of seconds > 0")
    return value


def main(argv: Sequence[str] | None = None) -> int:
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exit_:
        return exit_.code if isinstance(exit_.code, int) else 2
    try:
        return _main(args)
    except (UserError, UsageError) as err:
        if isinstance(err, UserError):
            report.findings(err.findings)
        else:
            print(f"hfsm-verify: {err}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("hfsm-verify: stopped", file=sys.stderr)
        return 130


def _main(args: argparse.Namespace) -> int:
    from hfsm.runtime.run import RunOptions
    from hfsm.verify.build import bound_of, input_values, unobserved, verify_program
    from hfsm.verify.choices import Chooser
    from hfsm.verify.properties import Properties
    from hfsm.verify.props import read_props
    from hfsm.verify.search import Budget, explore
    from hfsm.verify.values import read_values

    with stdout_to_stderr():
        registry = Registry.discover()
        factories = _factories()
    args.file = machine_path(args.file, args.lib, registry)
    loaded = load([args.file], libs=args.lib, registry=registry)
    report.findings(loaded.warnings)
    top = loaded.roots[0]
    agents = _agents(args.agents)
    agent_params = _agent_params(args, agents, top, registry)
    every = all(a in agent_params for a in agents)  # then --param alone need not give every param
    params = agent_params[agents[0]] if every else top_params(args.param, None, top, registry)
    states = {s for mf in loaded.machines.values() for s in mf.model.states}
    props = read_props(args.props, states) if args.props else None
    values = read_values(args.values)
    inputs = input_values({n: f.inputs() for n, f in factories.items()}, values.inputs)
    values.inputs = inputs
    bound = bound_of(top, args.bound, {a: agent_params.get(a, params) for a in agents})
    chooser = Chooser()
    program = verify_program(loaded, registry, args.stand_in, values, chooser, args.dt)
    scopes = _scopes(args.scope, agents)
    options = RunOptions(top.name, agents, params, args.seed, bound, agent_params=agent_params, scopes=scopes)
    budget = Budget(args.loss, args.delay, args.fail, span_ticks(bound, args.dt), args.max_states)
    budget.max_seconds = args.max_seconds or budget.max_seconds
    failures = top.model.failure_outcomes
    check = Properties(failures, args.goal == "success", props, bound)
    timeless = unobserved(loaded, bool(props and props.left_within)) if args.keys == "values" else None
    result = explore(program, options, budget, check, chooser, inputs, timeless, args.workers)
    out = args.out or args.file.with_name(args.file.stem + ".ce.jsonl")
    verdict: dict[str, Any] = {
        "verdict": "ok" if result.exhausted else "bounded",
        "kind": None,
        "agent": None,
        "states": result.states,
        "exhausted": result.exhausted,
        "seconds": round(result.seconds, 3),
        "states_per_second": round(result.states / result.seconds) if result.seconds else 0,
        "counterexample": None,
    }
    if result.violation is not None:
        from hfsm.cli.tracefile import TraceFile
        from hfsm.verify.counterexample import replay

        v = result.violation
        setup = {
            "top": top.name, "agents": agents, "params": params, "agent_params": agent_params,
            "seed": args.seed, "dt": args.dt,
            "bound": bound, "stand_ins": args.stand_in, "outputs": values.outputs, "inputs": inputs,
            **({"scripts": values.scripts} if values.scripts else {}),
            **({"scopes": {a: [n, list(m)] for a, (n, m) in scopes.items()}} if scopes else {}),
            "loss": args.loss, "delay": args.delay, "fail": args.fail,
            "violation": {"kind": v.kind, "agent": v.agent, "t": round(v.tick * args.dt, 9), "text": v.text},
            "choices": [c.as_json(args.dt) for c in v.choices],
        }  # fmt: skip
        trace = TraceFile(out)
        try:
            replay(loaded, registry, setup, trace)
        finally:
            trace.close()
        verdict.update(verdict="violation", kind=v.kind, agent=v.agent, counterexample=str(out))
        _tell(args, out, setup)
    else:
        unreached = sorted(set(top.model.outcomes) - result.top_outcomes)  # timeout: never asked for
        if unreached:
            line, col = top.doc.pos(("outcomes",))
            named = f"outcome{'s' * (len(unreached) > 1)} {', '.join(unreached)}"
            text = f"no run explored reaches {named} of '{top.name}'"
            report.findings([Finding(str(args.file), line, col, "W470", text, Severity.WARNING)])
    if args.json:
        print(json.dumps(verdict))
    else:
        how = "space exhausted" if result.exhausted else "stopped before the end"
        if result.violation is not None:
            how = "the first violation found ends the search"
        word = {"ok": "ok", "bounded": "no violation", "violation": "VIOLATION"}[verdict["verdict"]]
        rate = verdict["states_per_second"]
        print(f"{word}: {result.states} states in {result.seconds:.1f} s ({rate}/s), {how}", file=sys.stderr)
    return 1 if result.violation is not None else 0


def _agents(text: str) -> list[str]:
    agents = [a.strip() for a in text.split(",")]
    if any(not is_name(a) for a in agents) or len(set(agents)) != len(agents):
        raise UsageError(f"--agents {text!r}: distinct names matching ^[a-z][a-z0-9_]*$")
    return agents


def _scopes(given: list[str], agents: list[str]) -> dict[str, tuple[str, tuple[str, ...]]]:
    """`--scope NAME:AGENT,AGENT`: each agent listed runs under that scope (one scope an agent)."""
    scopes: dict[str, tuple[str, tuple[str, ...]]] = {}
    for text in given:
        name, sep, listed = text.partition(":")
        members = tuple(a.strip() for a in listed.split(",") if a.strip())
        unknown = [a for a in members if a not in agents]
        if not sep or not is_name(name) or not members or unknown:
            hint = did_you_mean(unknown[0], agents) if unknown else None
            raise UsageError(f"--scope {text!r}: NAME:AGENT,AGENT with agents of the run{hint or ''}")
        for agent in members:
            if agent in scopes:
                raise UsageError(f"--scope {text!r}: {agent} is already in scope '{scopes[agent][0]}'")
            scopes[agent] = (name, members)
    return scopes


def _agent_params(
    args: argparse.Namespace, agents: list[str], top: MachineFile, registry: Registry
) -> dict[str, dict[str, Any]]:
    """`--agent-param AGENT:K=V`: that agent's params are the `--param`s with these over them."""
    mine: dict[str, list[str]] = {}
    for text in args.agent_param:
        agent, sep, pair = text.partition(":")
        if not sep or agent not in agents:
            hint = did_you_mean(agent, agents) or f" (agents: {', '.join(agents)})"
            raise UsageError(f"--agent-param {text!r}: AGENT:K=V with an agent of the run{hint}")
        mine.setdefault(agent, []).append(pair)
    return {a: top_params([*args.param, *pairs], None, top, registry) for a, pairs in mine.items()}


def _tell(args: argparse.Namespace, out: Path, setup: dict[str, Any]) -> None:
    """The violation, and the choices that led there, on stderr."""
    v = setup["violation"]
    print(f"{args.file}: {v['kind']} ({v['agent']}) at t={v['t']:g} s: {v['text']}", file=sys.stderr)
    choices = setup["choices"]
    for c in choices[:SHOWN]:
        if c["kind"] == "message":
            how = "lost" if c.get("lost") else f"late by {c['delay']} ticks"
            print(f"  t={c['t']:g} s: {c['what']} {how}", file=sys.stderr)
        elif c["kind"] == "fail":
            print(f"  t={c['t']:g} s: {', '.join(c['agents'])} failed", file=sys.stderr)
        else:
            given = f" with {json.dumps(c['outputs'])}" if "outputs" in c else ""
            print(
                f"  t={c['t']:g} s: {c['what']} ended '{c['outcome']}' after {c['after']} ticks{given}",
                file=sys.stderr,
            )
    if len(choices) > SHOWN:
        print(f"  ... and {len(choices) - SHOWN} more choices (in {out})", file=sys.stderr)
    print(f"wrote {out}", file=sys.stderr)


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
