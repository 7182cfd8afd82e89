"""Time `hfsm-lsp` from a change to its diagnostics, on machine files of 500 states (and more).

The server runs as an editor runs it (a process on stdin/stdout); each change replaces the whole
text, alternately adding and removing a misspelt param in the first state (and each text new: a
comment on that line counts the changes, so no check is answered from a cache of earlier texts), and
the time is taken from writing the
change to reading the diagnostics published for it. Rewrites the bench_lsp section of
docs/PERFORMANCE.md (nothing else in that shared file). Target (issue 24): at most 100 ms on a
500-state file.
Usage: .venv/bin/python tools/bench_lsp.py [--sizes 500,2000] [--changes N] [--no-doc]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import IO, Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from docsection import write_section

ROOT = Path(__file__).resolve().parent.parent
TARGET_MS = 100.0


def machine_yaml(states: int) -> str:
    """States that wait a param's seconds in a row, a choice over a var every tenth, one timer."""
    lines = [
        f"doc: bench_lsp, {states} states.",
        "params:",
        "  pause: {type: float, default: 0.05}",
        "vars: {count: 0}",
        "outcomes: [done, failed]",
        "timer: 3600",
        "states:",
    ]
    for i in range(states):
        to = f"s{i + 1}" if i + 1 < states else "done"
        if i % 10 == 9:
            lines += [
                f"  s{i}:",
                "    choose:",
                f"      - if: vars.count > {i}",
                "        then: failed",
                f"      - else: {to}",
            ]
        else:
            lines.append(f'  s{i}: {{do: wait, with: {{seconds: "${{params.pause}}"}}, on: {{done: {to}}}}}')
    return "\n".join(lines) + "\n"


class Server:
    """hfsm-lsp over pipes: JSON-RPC messages with Content-Length headers."""

    def __init__(self) -> None:
        command = [sys.executable, "-m", "hfsm.cli.lsp"]
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, cwd=ROOT)
        self.next_id = 0

    def send(self, method: str, params: Any, *, request: bool = False) -> int:
        message: dict[str, Any] = {"jsonrpc": "2.0", "method": method, "params": params}
        if request:
            self.next_id += 1
            message["id"] = self.next_id
        body = json.dumps(message).encode()
        stdin: IO[bytes] = self.process.stdin  # type: ignore[assignment]
        stdin.write(b"Content-Length: %d\r\n\r\n%s" % (len(body), body))
        stdin.flush()
        return self.next_id

    def read(self) -> dict[str, Any]:
        stdout: IO[bytes] = self.process.stdout  # type: ignore[assignment]
        length = 0
        while (line := stdout.readline().strip()) != b"":
            if line.lower().startswith(b"content-length:"):
                length = int(line.split(b":")[1])
        message: dict[str, Any] = json.loads(stdout.read(length))
        return message

    def diagnostics(self, uri: str) -> list[Any]:
        while True:
            message = self.read()
            if message.get("method") == "textDocument/publishDiagnostics" and message["params"]["uri"] == uri:
                found: list[Any] = message["params"]["diagnostics"]
                return found

    def cpu_seconds(self) -> float:
        """User and system CPU seconds the server has used so far (Linux: /proc)."""
        fields = Path(f"/proc/{self.process.pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def close(self) -> None:
        self.send("shutdown", None, request=True)
        self.send("exit", None)
        self.process.wait(timeout=30)


def measure(states: int, changes: int) -> tuple[list[float], float, float]:
    """Milliseconds from each change to its diagnostics; from opening to the first ones; and the
    server's mean CPU milliseconds per change (steadier than wall time on a shared machine)."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / f"m{states}.yaml"
        text = machine_yaml(states)
        path.write_text(text, encoding="utf-8")
        uri = path.as_uri()
        server = Server()
        server.send(
            "initialize",
            {"processId": os.getpid(), "capabilities": {}, "initializationOptions": {"world": "none"}},
            request=True,
        )
        server.read()
        server.send("initialized", {})
        begin = time.perf_counter()
        server.send(
            "textDocument/didOpen",
            {"textDocument": {"uri": uri, "languageId": "yaml", "version": 1, "text": text}},
        )
        assert server.diagnostics(uri) == [], "the bench file must be clean"
        opened = (time.perf_counter() - begin) * 1000
        times = []
        cpu = server.cpu_seconds()
        for version in range(2, changes + 2):
            changed = text.replace("seconds", "secnds", 1) if version % 2 == 0 else text
            changed = changed.replace("s1}}\n", f"s1}}}} # change {version}\n", 1)  # never a text seen
            begin = time.perf_counter()
            server.send(
                "textDocument/didChange",
                {"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": changed}]},
            )
            found = server.diagnostics(uri)
            times.append((time.perf_counter() - begin) * 1000)
            assert len(found) == (1 if version % 2 == 0 else 0), found[:3]
        cpu = (server.cpu_seconds() - cpu) * 1000 / changes
        server.close()
    return times, opened, cpu


Row = tuple[int, list[float], float, float]  # states, ms per change, ms to open, server CPU ms per change


def stages(states: int, repeats: int = 10) -> dict[str, float]:
    """CPU milliseconds of each step of one check of the file, in process (the best of `repeats`)."""
    from hfsm import salvage
    from hfsm.checks import run_checks
    from hfsm.library import MachineFile
    from hfsm.lsp.reparse import Reparser
    from hfsm.model import Machine
    from hfsm.registry import Registry
    from hfsm.yamlio import parse_text

    text, registry = machine_yaml(states), Registry()
    best: dict[str, float] = {}

    def timed(name: str, step: Any, *args: Any) -> Any:
        begin = time.process_time()
        result = step(*args)
        best[name] = min(best.get(name, 1e9), (time.process_time() - begin) * 1000)
        return result

    reparser = Reparser()
    reparser.parse(text, "m.yaml")
    for n in range(repeats):
        doc = timed("read the whole YAML", parse_text, text, "m.yaml")
        changed = text.replace("s1}}\n", f"s1}}}} # change {n}\n", 1)
        timed("read again from the changed state", reparser.parse, changed, "m.yaml")
        model = timed("validate (schema)", salvage.validate, Machine, doc)[0]
        machine = MachineFile("m", Path("m.yaml"), doc, model)
        timed("every check", run_checks, {"m": machine}, registry, {})
    return best


def section(
    rows: list[Row], changes: int, steps: dict[str, float] | None = None, load_before: float = 0.0
) -> list[str]:
    load = os.getloadavg()[0]
    lines = [
        "## The language server: from a change to its diagnostics (bench_lsp)",
        "",
        f"Measured by `tools/bench_lsp.py` on {platform.machine()}, {os.cpu_count()} CPUs, Python "
        f"{platform.python_version()}, {time.strftime('%Y-%m-%d')}; load average {load_before:.1f} at the "
        f"start, {load:.1f} at the end (a shared VM of 2 CPUs).",
        f"Command: `.venv/bin/python tools/bench_lsp.py` ({changes} changes per file). `hfsm-lsp` runs as "
        "editors run it, a process on stdin/stdout; each change sends the whole text, alternately "
        "misspelling and mending a param's name in the first state (each text new: a comment on that line "
        "counts the changes), and is "
        "timed from writing it to reading the diagnostics "
        "published for it (the file read, every check run over it and its callees, the diagnostics sent). "
        "The file: call states with an expression param and a choice every tenth state, under a machine "
        "timer. A change inside one state reads that state alone and mends the last document "
        "(`hfsm/lsp/reparse.py`); expression checks are remembered by text; the collector is paused "
        "during a check.",
        "",
        "| states | median ms | 90th percentile ms | slowest ms | server CPU ms per change (mean) "
        "| first diagnostics after opening, ms |",
        "|---:|---:|---:|---:|---:|---:|",
    ]
    for states, times, opened, cpu in rows:
        ordered = sorted(times)
        p90 = ordered[int(0.9 * (len(ordered) - 1))]
        lines.append(
            f"| {states:,} | {statistics.median(times):.0f} | {p90:.0f} | {max(times):.0f} | {cpu:.0f} "
            f"| {opened:.0f} |"
        )
    small = next((r for r in rows if r[0] == 500), None)
    if small is not None:
        ordered = sorted(small[1])
        wall, p90, cpu = statistics.median(ordered), ordered[int(0.9 * (len(ordered) - 1))], small[3]
        met = "**met**" if p90 <= TARGET_MS else "**not met** on this machine's load"
        lines += [
            "",
            f"- Target: at most {TARGET_MS:.0f} ms from a change to its diagnostics on a 500-state file: "
            f"median {wall:.0f} ms, 90th percentile {p90:.0f} ms, {met}; the server's own CPU time per "
            f"change is {cpu:.0f} ms.",
        ]
    lines.append(
        "- The first diagnostics after opening include the server's one-off work (discovering the primitives "
        "and the worlds' inputs)."
    )
    if steps:
        shown = ", ".join(f"{name} {ms:.0f} ms" for name, ms in steps.items())
        lines.append(f"- Where the CPU goes on the 500-state file (in process, best of 10): {shown}.")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="500,2000")
    parser.add_argument("--changes", type=int, default=40)
    parser.add_argument("--no-doc", action="store_true", help="print, do not rewrite docs/PERFORMANCE.md")
    args = parser.parse_args()
    rows = []
    load_before = os.getloadavg()[0]
    for states in (int(s) for s in args.sizes.split(",")):
        times, opened, cpu = measure(states, args.changes)
        rows.append((states, times, opened, cpu))
        median = statistics.median(times)
        print(
            f"{states} states: median {median:.1f} ms, max {max(times):.1f} ms, CPU {cpu:.1f} ms", flush=True
        )
    lines = section(rows, args.changes, stages(500), load_before)
    if args.no_doc:
        print("\n".join(lines))
    else:
        write_section(ROOT / "docs" / "PERFORMANCE.md", "bench_lsp", lines)


if __name__ == "__main__":
    main()
