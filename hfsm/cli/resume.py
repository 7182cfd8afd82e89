"""`hfsm-run FILE --resume TRACE@T`: run again what a trace recorded, up to T, then go on.

Every trace begins with a `run` record: the flags that decide what happens (seed, agents, params,
world, scenario, autonomy, …; never the outputs) and a digest of each machine file. A resumed run
takes those flags from the trace, replays its operator records up to T, and checks, line by line as
it writes them, that its trace up to T is the old one, byte for byte; after T it goes on as any run
(with the machine files as they are now) and its trace says so with a `resume` record. An edit of
the machine files is accepted when every state on each agent's active path at T still exists and
calls what it called.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from hfsm.autonomy import Decision, decision_of
from hfsm.cli.prefix import PrefixCheck
from hfsm.errors import UsageError
from hfsm.library import MachineFile
from hfsm.load import Loaded
from hfsm.model import CallState, ParallelState
from hfsm.runtime.program import span_ticks
from hfsm.yamlio import decode, read_bytes

# What a run writes or how it is watched: never part of what it does.
OUTPUTS = frozenset({
    "file", "trace", "json", "quiet", "monitor", "monitor_hold", "realtime", "resume", "operator", "max_time",
    "breaks", "traceback", "check", "strict", "schema", "list", "out", "video", "no_video", "progress",
})  # fmt: skip


def settings_argv(parser: argparse.ArgumentParser, argv: Sequence[str]) -> list[str]:
    """`argv` without FILE and without the flags in OUTPUTS (with their values)."""
    takes: dict[str, int] = {}
    for action in parser._actions:
        for option in action.option_strings:
            takes[option] = -1 if action.dest in OUTPUTS else 0
            if action.dest in OUTPUTS and action.nargs != 0:
                takes[option] = -2 if action.nargs == "?" else -3
    out: list[str] = []
    tokens = list(argv)
    i = 0
    positional = False
    while i < len(tokens):
        token = tokens[i]
        name = token.split("=", 1)[0]
        how = takes.get(name, 0)
        i += 1
        if how == 0:
            if not token.startswith("-") and not positional:
                positional = True  # FILE
                continue
            out.append(token)
        elif "=" not in token and how == -3 and i < len(tokens):
            i += 1  # the flag's value
        elif "=" not in token and how == -2 and i < len(tokens) and not tokens[i].startswith("-"):
            i += 1
    return out


def digest(machines: dict[str, MachineFile]) -> dict[str, str]:
    return {
        name: hashlib.sha256(mf.path.read_bytes()).hexdigest()[:16] for name, mf in sorted(machines.items())
    }


def header(top: str, settings: list[str], loaded: Loaded) -> dict[str, Any]:
    """The first record of a trace: what a resumed run needs to run the same way."""
    return {
        "t": 0.0,
        "agent": None,
        "path": [],
        "kind": "run",
        "machine": top,
        "args": settings,
        "machines": digest(loaded.machines),
    }


@dataclass
class Resume:
    path: Path
    at: float  # T, seconds
    head: dict[str, Any]
    lines: list[str]  # the old trace's lines after its header, each without its newline
    prefix: int  # how many of them are at or before T
    decisions: list[Decision] = field(default_factory=list)


def read_resume(text: str, dt_of: Any) -> Resume:
    """`TRACE@T` read: the trace, its header, its lines up to T. `dt_of(head)` gives the run's dt."""
    where, sep, at = text.rpartition("@")
    try:
        seconds = float(at)
    except ValueError:
        seconds = math.nan
    if not sep or not where or not math.isfinite(seconds) or seconds < 0:
        raise UsageError(f"--resume {text!r}: write TRACE@SECONDS, e.g. out/run.jsonl@12.5")
    path = Path(where)
    lines = decode(read_bytes(path, where), where).splitlines()
    try:
        head = json.loads(lines[0]) if lines else {}
    except ValueError:
        head = {}
    if not isinstance(head, dict) or head.get("kind") != "run":
        raise UsageError(f"--resume: {where} does not begin with a `run` record (a trace of this version)")
    tick = span_ticks(seconds, dt_of(head))
    body = lines[1:]
    prefix = 0
    last = -1.0
    for line in body:
        t = json.loads(line).get("t", 0.0)
        last = t
        if span_ticks(t, dt_of(head)) > tick:
            break
        prefix += 1
    else:
        if last < seconds:
            raise UsageError(f"--resume: {where} ends at t={last:g} s, before {seconds:g} s")
    return Resume(path, seconds, head, body, prefix)


def operator_records(resume: Resume) -> list[Decision]:
    out = []
    for line in resume.lines[: resume.prefix]:
        if '"operator"' in line:
            r = json.loads(line)
            if r.get("kind") == "operator":
                out.append(decision_of(r))
    return out


def check_edit(resume: Resume, loaded: Loaded) -> list[str]:
    """Each state on an agent's active path at T that no longer exists or calls something else;
    and the machines whose files changed (for the `resume` record)."""
    active: dict[tuple[str, tuple[str, ...]], str] = {}
    for line in resume.lines[: resume.prefix]:
        if '"enter"' not in line and '"exit"' not in line:
            continue
        r = json.loads(line)
        key = (r.get("agent"), tuple(r.get("path", ())))
        if r.get("kind") == "enter":
            active[key] = r.get("do", "")
        elif r.get("kind") == "exit":
            for other in [k for k in active if k[0] == key[0] and k[1][: len(key[1])] == key[1]]:
                del active[other]
    problems = []
    for (agent, path), do in sorted(active.items()):
        problem = _changed(loaded, path, do)
        if problem:
            problems.append(f"{agent}: {'/'.join(path)}: {problem}")
    return sorted(set(problems))


def _changed(loaded: Loaded, path: tuple[str, ...], do: str) -> str:
    """Why the state (or region) at `path` is not what it was, or ''."""
    machine = loaded.machines.get(path[0])
    if machine is None:
        return f"the machine '{path[0]}' is not loaded any more"
    i = 1
    while i < len(path):
        state = machine.model.states.get(path[i])
        if state is None:
            return f"'{machine.name}' has no state '{path[i]}' any more"
        callee = state.do if isinstance(state, CallState) else ""
        if isinstance(state, ParallelState) and i + 1 < len(path):
            region = state.parallel.get(path[i + 1])
            if region is None:
                return f"'{machine.name}/{path[i]}' has no region '{path[i + 1]}' any more"
            callee, i = region.do, i + 1
        if i == len(path) - 1:
            return "" if callee == do else f"it calls '{callee or 'nothing'}' now, not '{do}'"
        machine = loaded.machines.get(callee)
        if machine is None:
            return f"'{path[i]}' calls '{callee}', which is no machine any more"
        i += 1
    return ""


def prepare(args: argparse.Namespace, parser: argparse.ArgumentParser, argv: Sequence[str]) -> None:
    """The flags a trace's header keeps (`args.settings`); with `--resume`, the trace's own flags
    take their places (`args.resumed`: the Resume)."""
    args.settings = settings_argv(parser, argv)
    args.resumed = None
    if args.resume is None:
        return

    def reparse(settings: list[str]) -> argparse.Namespace:
        try:
            return parser.parse_args([str(args.file or "x"), *settings])
        except SystemExit:
            raise UsageError(f"--resume: the trace's flags are not this version's: {settings}") from None

    resume = read_resume(args.resume, lambda head: reparse(list(head.get("args", []))).dt)
    old = reparse(list(resume.head["args"]))
    for dest, value in vars(old).items():
        if dest not in OUTPUTS:
            setattr(args, dest, value)
    args.settings = list(resume.head["args"])
    resume.decisions = operator_records(resume)
    args.resumed = resume


def edited(resume: Resume, loaded: Loaded) -> list[str]:
    """Exit 2 naming each state of an active path at T that changed; else the machines edited."""
    problems = check_edit(resume, loaded)
    if problems:
        raise UsageError(
            f"--resume: the machine files changed what runs at t={resume.at:g} s:\n  " + "\n  ".join(problems)
        )
    old: dict[str, str] = resume.head.get("machines", {})
    new = digest(loaded.machines)
    return sorted(n for n in old.keys() | new.keys() if old.get(n) != new.get(n))


def begin(trace: Any, args: argparse.Namespace, loaded: Loaded, dt: float) -> Any:
    """The trace's header written; the sink the run writes to (checked up to T when resuming)."""
    if trace is None:
        return None
    trace.write(header(loaded.roots[0].name, args.settings, loaded))
    if args.resumed is None:
        return trace
    return PrefixCheck(trace, args.resumed, args.edited, dt)


def end(sink: Any, result: Any) -> None:
    """A resumed run that ended before T: its trace must hold all of the old one's up to T."""
    if not isinstance(sink, PrefixCheck) or not sink.checking:
        return
    if sink.seen < sink.resume.prefix:
        result.error = result.error or (
            f"--resume: the run wrote {sink.seen} lines up to its end, where {sink.resume.path} has "
            f"{sink.resume.prefix} up to t={sink.resume.at:g} s"
        )
    else:
        sink.done(sink.last)
