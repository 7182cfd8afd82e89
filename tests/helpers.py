"""Test helpers: write machine files, run them in process."""

from __future__ import annotations

import contextlib
import importlib.util
import json
import re
import signal
import sys
import textwrap
from collections.abc import Iterator, Sequence
from pathlib import Path
from types import FrameType, ModuleType
from typing import Any

import pytest

from hfsm.cli.run import main
from hfsm.load import load
from hfsm.registry import Registry
from hfsm.runtime.failing import Failure
from hfsm.runtime.program import Program, machine_params
from hfsm.runtime.run import RunOptions, RunResult, run
from hfsm.trace import ListTrace, TraceSink
from hfsm.world import NullWorld, World

ROOT = Path(__file__).resolve().parent.parent
SNIPPET = re.compile(r"^ *\d* \|( .*)?$")  # the source line and caret printed under a finding


def finding_lines(err: str) -> list[str]:
    """The lines of stderr less the source lines and carets printed under each finding."""
    return [line for line in err.splitlines() if not SNIPPET.match(line)]


def hfsm_run(capsys: pytest.CaptureFixture[str], *argv: object) -> tuple[int, str, str]:
    """`hfsm-run ARGV` in process: its exit code, stdout and stderr."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def sim_json(
    capsys: pytest.CaptureFixture[str], machine: Path, scenario: Path, params: Sequence[str], *,
    seed: int = 0, max_time: float = 300.0,
) -> dict[str, Any]:
    """`hfsm-run MACHINE --scenario SCENARIO --json` with each `--param`, no video: its JSON result."""
    argv: list[object] = [machine, "--scenario", scenario, "--seed", seed, "--json", "--no-video", "--quiet",
                          "--progress", 0, "--max-time", max_time]
    for param in params:
        argv += ["--param", param]
    code, out, _ = hfsm_run(capsys, *argv)
    assert code == 0
    result: dict[str, Any] = json.loads(out)
    return result


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / f"{name}.yaml"
    path.write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    return path


def sender_states(message: str, keep: str = "all") -> str:
    """Machine states (YAML, at the indentation of a `states:` entry) of a sender: `say` sends
    `message` to agent b with data {n}, `params.times` times 0.05 s apart, then goes to `done`;
    `keep` is send's (a literal or an expression). Needs `vars.n` and `params.times`."""
    return f"""
  say:
    do: send
    with: {{message: {message}, to: b, keep: "{keep}", data: {{n: "${{vars.n}}"}}}}
    on: {{sent: count}}
  count:
    do: set
    with: {{n: "${{vars.n + 1}}"}}
    on: {{done: more}}
  more:
    choose:
      - if: "vars.n < params.times"
        then: pause
      - else: done
  pause:
    do: wait
    with: {{seconds: 0.05}}
    on: {{done: say}}"""


def execute(
    path: Path,
    *,
    agents: Sequence[str] = ("robot",),
    params: dict[str, Any] | None = None,
    registry: Registry | None = None,
    world: World | None = None,
    dt: float = 0.05,
    max_time: float = 3600.0,
    seed: int = 0,
    failures: Sequence[Failure] = (),
    sink: TraceSink | None = None,
) -> tuple[RunResult, list[dict[str, Any]]]:
    """Load and run `path`; its result, and the trace's records (none when `sink` takes them instead)."""
    registry = registry or Registry()
    loaded = load([path], registry=registry)
    top = loaded.roots[0]
    full = machine_params(top, params or {})
    program = Program(loaded.machines, registry, dt)
    trace = ListTrace()
    options = RunOptions(top.name, list(agents), full, seed, max_time, failures)
    result = run(program, world or NullWorld(), options, sink or trace)
    if sink is not None:
        sink.close()
    return result, trace.records


def load_tool(name: str) -> ModuleType:
    """Import a script of tools/ from its file (tools/ is not a package to install)."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "tools" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up while the class is made
    spec.loader.exec_module(module)
    return module


def check_nesting(records: list[dict[str, Any]]) -> None:
    """Every enter has its exit; a path enters inside an open one and exits after all below it."""
    open_paths: dict[str, set[tuple[str, ...]]] = {}
    for record in records:
        opened = open_paths.setdefault(record["agent"], set())
        path = tuple(record["path"])
        if record["kind"] == "enter":
            assert path not in opened and (len(path) == 1 or path[:-1] in opened), (opened, record)
            opened.add(path)
        elif record["kind"] == "exit":
            assert path in opened, (opened, record)
            assert not any(p[: len(path)] == path and p != path for p in opened), (opened, record)
            opened.remove(path)
    assert all(not s for s in open_paths.values()), open_paths


class Hang(Exception):
    pass


@contextlib.contextmanager
def watchdog(seconds: int) -> Iterator[None]:
    """A hang of the code inside becomes the exception Hang after `seconds` (SIGALRM)."""

    def ring(_signum: int, _frame: FrameType | None) -> None:
        raise Hang(f"no answer within {seconds} s")

    old = signal.signal(signal.SIGALRM, ring)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
