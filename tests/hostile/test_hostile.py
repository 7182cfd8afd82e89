"""Every hostile file through every command that reads its kind: a clear error (exit 1 or 2, a message
naming the file), never a traceback. In process (`main(argv)`), with a watchdog that turns a hang into
a failure; the largest cases also in a child process whose peak memory is read (os.wait4)."""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys
from collections.abc import Callable, Sequence
from pathlib import Path

import pytest
from helpers import watchdog

from hfsm.cli import graph, monitor, run, test
from hostile import corpus

ROOT = Path(__file__).resolve().parents[2]
HANG_S = 300  # far above any honest answer (10 s on a quiet machine, a minute at load 25): a hang guard
MEMORY_MB = 500
Main = Callable[[Sequence[str] | None], int]




def call(main: Main, argv: list[str]) -> tuple[int, str]:
    out, err = io.StringIO(), io.StringIO()
    with watchdog(HANG_S), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, err.getvalue() + out.getvalue()


def assert_clear(code: int, text: str, path: Path) -> None:
    assert code in (1, 2), text[-2000:]
    assert "Traceback" not in text, text[-2000:]
    assert path.name in text or str(path) in text, text[-2000:]


def machine_commands(path: Path, out: Path) -> list[tuple[Main, list[str]]]:
    return [
        (run.main, [str(path), "--check", "--world", "none"]),
        (run.main, [str(path), "--world", "none", "--quiet", "--max-time", "5"]),
        (graph.main, [str(path), "-o", str(out)]),
    ]


def made(tmp_path: Path, name: str, content: bytes | str) -> Path:
    return corpus.write(tmp_path, name, content)


@pytest.mark.parametrize("name", sorted(corpus.MACHINES))
def test_machine_files(name: str, tmp_path: Path) -> None:
    path = made(tmp_path, name, corpus.MACHINES[name])
    for main, argv in machine_commands(path, tmp_path / "out"):
        code, text = call(main, argv)
        assert_clear(code, text, path)


@pytest.mark.parametrize("name", sorted(corpus.SPECIAL))
def test_special_files(name: str, tmp_path: Path) -> None:
    path = corpus.SPECIAL[name](tmp_path)
    for main, argv in [*machine_commands(path, tmp_path / "out"), (test.main, [str(path)])]:
        code, text = call(main, argv)
        if main is graph.main and name == "folder":  # a folder is a drawing's input: the legend alone
            assert code == 0 and f"no machine files in {path}" in text
            continue
        assert_clear(code, text, path)


@pytest.mark.parametrize("name", sorted(corpus.TESTS))
def test_behaviour_test_files(name: str, tmp_path: Path) -> None:
    path = made(tmp_path, name, corpus.TESTS[name])
    code, text = call(test.main, [str(path)])
    assert_clear(code, text, path)


@pytest.mark.parametrize("name", sorted(corpus.SCENARIOS))
def test_scenario_files(name: str, tmp_path: Path) -> None:
    path = made(tmp_path, name, corpus.SCENARIOS[name])
    top = str(ROOT / "machines" / "move_furniture.yaml")
    code, text = call(run.main, [top, "--scenario", str(path), "--check"])
    assert_clear(code, text, path)


@pytest.mark.parametrize("name", sorted(corpus.HISTORIES))
def test_history_files(name: str, tmp_path: Path) -> None:
    path = made(tmp_path, name, corpus.HISTORIES[name])
    top = str(ROOT / "machines" / "tararc.yaml")
    code, text = call(run.main, [top, "--history", str(path), "--check"])
    assert_clear(code, text, path)


@pytest.mark.parametrize("name", sorted(corpus.TRACES))
def test_trace_files(name: str, tmp_path: Path) -> None:
    path = made(tmp_path, name, corpus.TRACES[name])
    code, text = call(monitor.main, [str(path), "--for", "0"])
    assert_clear(code, text, path)
    hello = str(ROOT / "examples" / "hello.yaml")
    code, text = call(graph.main, [hello, "--trace", str(path), "-o", str(tmp_path / "out")])
    assert_clear(code, text, path)


HEAVY = ["billion_laughs.yaml", "deep_flow.yaml", "garbage_big.yaml", "long_line.yaml", "many_nodes.yaml"]


# A child's peak resident set counts what its parent had resident when it forked (Linux keeps it over
# exec), so the command is started by a small launcher whose own peak is a few MB.
LAUNCH = """
import resource, subprocess, sys
code = subprocess.run(sys.argv[2:]).returncode
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
open(sys.argv[1], "w").write(f"{code} {peak}")
"""


def peak_run(command: list[str], cwd: Path) -> tuple[int, str, float]:
    """Exit code, what it printed, and its peak resident memory in MB."""
    log, result = cwd / "log.txt", cwd / "peak.txt"
    with log.open("wb") as out:
        launcher = subprocess.Popen([sys.executable, "-c", LAUNCH, str(result), *command], stdout=out,
                                    stderr=out, cwd=cwd)
        try:
            with watchdog(HANG_S):
                launcher.wait()
        finally:
            if launcher.returncode is None:
                launcher.kill()
    code, peak = result.read_text().split()
    return int(code), log.read_text(errors="replace"), int(peak) / 1024


@pytest.mark.slow
@pytest.mark.parametrize("name", [*HEAVY, "fifty_mb"])
def test_the_largest_stay_within_memory(name: str, tmp_path: Path) -> None:
    path = corpus.SPECIAL[name](tmp_path) if name in corpus.SPECIAL else made(tmp_path, name, corpus.MACHINES[name])
    command = [str(Path(sys.executable).parent / "hfsm-run"), str(path), "--check", "--world", "none"]
    code, text, mb = peak_run(command, tmp_path)
    assert_clear(code, text, path)
    assert mb < MEMORY_MB
