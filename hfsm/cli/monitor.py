"""hfsm-monitor TRACE.jsonl [--port P] [--lib DIR]… [--machine FILE]: the monitor's page over a
finished trace (the replay of a run written by `hfsm-run --trace`), until Ctrl-C."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hfsm.cli.quiet import stdout_to_stderr
from hfsm.errors import UsageError, UserError
from hfsm.library import PROJECT_MACHINES
from hfsm.trace import RECORD_SHAPE, is_record, json_line

MAX_TRACE_BYTES = 1 << 30


class TraceError(UsageError):
    """A trace that cannot be read, at its FILE:LINE:COL."""


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="hfsm-monitor", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    p.add_argument("trace", type=Path, metavar="TRACE.jsonl", help="a trace written by hfsm-run --trace")
    p.add_argument("--port", type=int, default=0, help="port on 127.0.0.1 (default: any free port)")
    p.add_argument(
        "--lib",
        action="append",
        type=Path,
        default=[],
        metavar="DIR",
        help="more folders to find the run's machines in",
    )
    p.add_argument("--machine", type=Path, metavar="FILE", help="the run's top machine file")
    p.add_argument(
        "--for",
        dest="seconds",
        type=float,
        default=None,
        metavar="S",
        help="serve for S seconds, then exit (default: until Ctrl-C)",
    )
    return p


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        records, svgs = replay(args.trace, args.lib, args.machine)
        from hfsm.monitor.hub import Hub
        from hfsm.monitor.serve import Server, hold

        video = next(
            (v for v in (args.trace.with_suffix(".mp4"), args.trace.with_suffix(".webm")) if v.is_file()),
            None,
        )
        server = Server(Hub(records), svgs, args.trace.name, args.port, video)
    except UserError as err:
        for finding in err.findings:
            print(finding.format(), file=sys.stderr)
        return 2
    except TraceError as err:
        print(err, file=sys.stderr)
        return 2
    except UsageError as err:
        print(f"hfsm-monitor: {err}", file=sys.stderr)
        return 2
    server.start()
    print(f"hfsm-monitor: serving {args.trace} at {server.url} (Ctrl-C to stop)", file=sys.stderr, flush=True)
    try:
        hold(args.seconds)
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()
    return 0


def replay(
    trace: Path, libs: list[Path], machine: Path | None = None
) -> tuple[list[dict[str, Any]], dict[str, str]]:
    """A trace's records and the drawings of its machines (`machine`, else found by the trace's top
    name beside the trace, in `libs` or in the project's machines)."""
    records = read_trace(trace)
    top = machine or find_machine(top_name(records, trace), [trace.parent, *libs])
    return records, drawings(top, libs) if top is not None else {}


def read_trace(path: Path) -> list[dict[str, Any]]:
    """Every record of a JSONL trace (the run's own records have no agent); a line that is not a JSON
    object is `FILE:LINE: message`."""
    if not path.is_file():
        raise UsageError(f"{path}: not a trace file")
    if path.stat().st_size > MAX_TRACE_BYTES:
        raise UsageError(f"{path}: over {MAX_TRACE_BYTES >> 20} MiB; cut it or use a shorter run")
    records = []
    with path.open(encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, start=1):
            if not line.strip():
                continue
            try:
                record = json_line(line.rstrip("\n"))
            except json.JSONDecodeError as exc:
                raise TraceError(f"{path}:{number}:{exc.colno}: not a trace record: {exc.msg}") from None
            except ValueError as exc:
                raise TraceError(f"{path}:{number}:1: not a trace record: {exc}") from None
            if not is_record(record):
                raise TraceError(f"{path}:{number}:1: not a trace record ({RECORD_SHAPE})")
            records.append(record)
    return records


def top_name(records: list[dict[str, Any]], path: Path) -> str:
    for record in records:
        if record["path"]:
            return str(record["path"][0])
    raise UsageError(f"{path}: the trace has no record of a machine")


def find_machine(name: str, folders: list[Path]) -> Path | None:
    for folder in [*folders, PROJECT_MACHINES]:
        for suffix in (".yaml", ".yml"):
            candidate = folder / f"{name}{suffix}"
            if candidate.is_file():
                return candidate
    print(
        f"hfsm-monitor: no machine file '{name}' found (use --machine): the page shows paths only",
        file=sys.stderr,
    )
    return None


def drawings(top: Path, libs: list[Path]) -> dict[str, str]:
    """SVG of every machine the run can reach (the checks run as for hfsm-run)."""
    from hfsm.load import load
    from hfsm.monitor.figures import machine_svgs
    from hfsm.registry import Registry

    with stdout_to_stderr():
        registry = Registry.discover()
    loaded = load([top], libs=libs, registry=registry)
    return machine_svgs(loaded, registry)


def entry() -> None:
    sys.exit(main())


if __name__ == "__main__":
    entry()
