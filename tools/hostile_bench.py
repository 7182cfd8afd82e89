"""CPU time of every hostile file of tests/hostile/corpus.py through the command that reads its kind
(in process: wall time on the shared machine says more of the load than of the file), and the
peak memory of the largest in a child process, as a user runs them (os.wait4). The numbers go between
`<!-- hostile:start -->` and `<!-- hostile:end -->`
in docs/ROBUSTNESS.md; the tests assert no traceback and the memory bound, never the time.

    nice -n 15 .venv/bin/python tools/hostile_bench.py
"""

from __future__ import annotations

import contextlib
import io
import os
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))
sys.path.insert(0, str(ROOT))

from hostile import corpus  # noqa: E402
from hostile.test_hostile import HEAVY, peak_run  # noqa: E402

from hfsm.cli import monitor, run, test  # noqa: E402
from tools.docsection import write_section  # noqa: E402

BIN = Path(sys.executable).parent
Main = Callable[[Sequence[str] | None], int]


def in_process(kind: str, path: Path, out: Path) -> tuple[Main, list[str]]:
    if kind == "machine":
        return run.main, [str(path), "--check", "--world", "none"]
    if kind == "test":
        return test.main, [str(path)]
    if kind == "scenario":
        return run.main, [str(ROOT / "machines" / "move_furniture.yaml"), "--scenario", str(path), "--check"]
    if kind == "history":
        return run.main, [str(ROOT / "machines" / "tararc.yaml"), "--history", str(path), "--check"]
    return monitor.main, [str(path), "--for", "0"]


def cpu_seconds(main: Main, argv: list[str]) -> tuple[int, float]:
    """Exit code and CPU seconds of one command in this process (what it prints is dropped)."""
    start = time.process_time()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        code = main(argv)
    return code, time.process_time() - start


def peak_mb(path: Path, cwd: Path) -> tuple[int, float, float]:
    """Exit code, wall seconds and peak resident MB of `hfsm-run FILE --check` (started by a small
    launcher: a child's peak counts what its parent had resident when it forked)."""
    command = [str(BIN / "hfsm-run"), str(path), "--check", "--world", "none"]
    start = time.monotonic()
    code, _, mb = peak_run(command, cwd)
    return code, time.monotonic() - start, mb


def main() -> int:
    kinds = {"machine": corpus.MACHINES, "test": corpus.TESTS, "scenario": corpus.SCENARIOS,
             "history": corpus.HISTORIES, "trace": corpus.TRACES}
    rows: list[tuple[str, int, float]] = []
    heavy: list[tuple[str, int, float, float]] = []
    with tempfile.TemporaryDirectory() as tmp:
        for kind, files in kinds.items():
            for name, content in sorted(files.items()):
                folder = Path(tmp) / f"{kind}-{len(rows)}"
                folder.mkdir()
                path = corpus.write(folder, name, content)
                code, cpu = cpu_seconds(*in_process(kind, path, folder / "out"))
                rows.append((f"{kind} {name}", code, cpu))
                print(f"{kind:9} {name:32} exit {code} {cpu:5.2f} s CPU", flush=True)
        for name in [*HEAVY, "fifty_mb"]:
            folder = Path(tmp) / f"heavy-{name}"
            folder.mkdir()
            path = corpus.SPECIAL[name](folder) if name in corpus.SPECIAL else corpus.write(
                folder, name, corpus.MACHINES[name])
            code, wall, mb = peak_mb(path, folder)
            heavy.append((name, code, wall, mb))
            print(f"child     {name:32} exit {code} {wall:5.1f} s {mb:6.0f} MB", flush=True)
    cpus = sorted(r[2] for r in rows)
    slowest = max(rows, key=lambda r: r[2])
    lines = [
        "Command: `nice -n 15 .venv/bin/python tools/hostile_bench.py` (the shared 2 cores, load average "
        f"{os.getloadavg()[0]:.1f})",
        "",
        f"- {len(rows)} hostile files (machine files, behaviour tests, scenarios, history files, traces), "
        f"each through the command that reads it: {sum(r[1] in (1, 2) for r in rows)} a clear error "
        f"(exit 1 or 2), {sum(r[1] == 0 for r in rows)} read as valid, none a traceback (tests/hostile)",
        f"- CPU time per file: median {cpus[len(cpus) // 2]:.2f} s, "
        f"largest {slowest[2]:.2f} s ({slowest[0]})",
        "- the largest, as `hfsm-run FILE --check` in a child process (peak resident memory, wall time "
        "on the loaded machine): " + ", ".join(f"{n} {mb:.0f} MB {wall:.1f} s" for n, _, wall, mb in heavy),
    ]
    print("\n".join(lines))
    write_section(ROOT / "docs" / "ROBUSTNESS.md", "hostile", lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
