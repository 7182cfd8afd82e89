"""`hfsm-run FILE --world none --replay CE.jsonl`: run a counterexample of `hfsm-verify` again, with
the stand-ins, values and choices its schedule gives (its params, agents and seed too)."""

from __future__ import annotations

import argparse
import sys

from hfsm.cli import report
from hfsm.errors import UsageError
from hfsm.load import Loaded
from hfsm.registry import Registry


def replayed(args: argparse.Namespace, loaded: Loaded, registry: Registry) -> int:
    from hfsm.cli.tracefile import TraceFile
    from hfsm.verify.counterexample import read_schedule, replay

    if args.world not in (None, "none"):
        raise UsageError("--replay runs in --world none")
    setup = read_schedule(args.replay)
    top = loaded.roots[0].name
    if setup.get("top") != top:
        raise UsageError(f"--replay {args.replay}: a counterexample of '{setup.get('top')}', not of '{top}'")
    trace = TraceFile(args.trace) if args.trace else None
    try:
        result = replay(loaded, registry, setup, trace)
    finally:
        if trace is not None:
            trace.close()
    if args.json:
        print(report.json_result(result, {}))
    else:
        report.text_result(result, {})
    violation = setup.get("violation", {})
    print(
        f"replayed: {violation.get('kind')} ({violation.get('agent')}): {violation.get('text')}",
        file=sys.stderr,
    )
    if result.error:
        print(f"error: {result.error}", file=sys.stderr)
    if trace is not None:
        print(f"wrote {args.trace}", file=sys.stderr)
    return result.exit_code
