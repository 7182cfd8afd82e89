"""Fuzzing as tests: `hfsm-run --check` of mutated machine files and random bytes, and random valid
machines run under `--world none`. In process (`main(argv)`), a bounded number of examples each.

The properties: no traceback, exit 0 or 2 (checks) or 0 or 1 (runs), and every line on stderr a
finding that starts with FILE:LINE:COL (or the `ok` line). A watchdog turns a hang into a failure.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import tempfile
from pathlib import Path

from helpers import finding_lines, watchdog
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hfsm.cli.run import main

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "machines").glob("*.yaml")) + sorted((ROOT / "examples").glob("*.yaml"))
TEXTS = {path.name: path.read_text(encoding="utf-8") for path in FILES}
FINDING = re.compile(r"^\S.*:\d+:\d+: (error|warning)\[[EW]\d+\]: \S")
HANG_S = 30  # far above any honest run here: a hang, not a speed test
EXAMPLES = int(os.environ.get("HFSM_FUZZ_EXAMPLES", "40"))  # more for a deeper search
FUZZ = settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=list(HealthCheck))
SNIPPETS = ["[", "]", "{", "}", ": ", ":", "- ", "#", "\t", "'", '"', "&a ", "*a", "!!str ", "---\n",
            "? ", "|", ">", "%", "@", "`", ",", "${", "}", "\n", "  ", "<<: ", "~", ".nan", "1e999"]




def hfsm_run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with watchdog(HANG_S), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def assert_findings_only(code: int, err: str, path: Path) -> None:
    assert "Traceback" not in err, err
    for line in finding_lines(err):
        if line.startswith("pybullet build time") or line == f"{path}: ok ({line.split('(')[-1]}":
            continue
        assert FINDING.match(line), f"not FILE:LINE:COL: {line!r} (exit {code})"


def check(text: str | bytes, name: str = "m.yaml") -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / name
        if isinstance(text, bytes):
            path.write_bytes(text)
        else:
            path.write_text(text, encoding="utf-8")
        code, out, err = hfsm_run(str(path), "--check")
    assert code in (0, 2), err
    assert out == ""
    assert_findings_only(code, err, path)


@st.composite
def mutated(draw: st.DrawFn) -> tuple[str, str]:
    name = draw(st.sampled_from(sorted(TEXTS)))
    lines = TEXTS[name].splitlines(keepends=True)
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["delete", "swap", "indent", "insert"]))
        i = draw(st.integers(0, max(0, len(lines) - 1)))
        if kind == "delete" and len(lines) > 1:
            del lines[i]
        elif kind == "indent":
            stripped = lines[i].lstrip(" ")
            lines[i] = " " * draw(st.integers(0, 12)) + stripped
        elif kind == "swap":
            tokens = "".join(lines).split(" ")
            a, b = draw(st.integers(0, len(tokens) - 1)), draw(st.integers(0, len(tokens) - 1))
            tokens[a], tokens[b] = tokens[b], tokens[a]
            lines = " ".join(tokens).splitlines(keepends=True) or [""]
        else:
            at = draw(st.integers(0, len(lines[i])))
            lines[i] = lines[i][:at] + draw(st.sampled_from(SNIPPETS)) + lines[i][at:]
    return name, "".join(lines)


@FUZZ
@given(mutated())
def test_mutated_machine_files_get_findings_not_tracebacks(case: tuple[str, str]) -> None:
    name, text = case
    check(text, name)


@FUZZ
@given(st.binary(max_size=400))
def test_random_bytes_get_findings_not_tracebacks(raw: bytes) -> None:
    check(raw)


@FUZZ
@given(st.text(alphabet="[]{}-:#'\"&*!|>?,\t\n abc01.$", max_size=200))
def test_random_yaml_punctuation_gets_findings_not_tracebacks(text: str) -> None:
    check(text)


def test_every_original_file_checks() -> None:
    for path in FILES:
        code, _, err = hfsm_run(str(path), "--check")
        assert code == 0, err


CALLS = {
    "wait": ('{{seconds: {seconds}}}', "done"),
    "set": ('{{n: "${{vars.n + {step}}}"}}', "done"),
    "log": ('{{text: "n=${{vars.n}} at ${{agent.id}}"}}', "done"),
    "send": ('{{message: ping, data: {{n: "${{vars.n}}"}}}}', "sent"),
}


@st.composite
def machines(draw: st.DrawFn) -> str:
    """A valid machine: built-in calls whose every outcome goes somewhere, choices that end in else."""
    n = draw(st.integers(1, 6))
    names = [f"s{i}" for i in range(n)]
    targets = st.sampled_from([*names, "done", "failure"])
    timer = draw(st.sampled_from(["", "timer: 5\n"]))
    lines = ["outcomes: [done, failure]", "vars: {n: 0}", timer.rstrip(), "states:"]
    for name in names:
        if draw(st.booleans()) or name == names[0]:
            call = draw(st.sampled_from(sorted(CALLS)))
            params, outcome = CALLS[call]
            given = params.format(seconds=draw(st.sampled_from([0, 0.05, 0.5, 2])), step=draw(st.integers(-2, 3)))
            arcs = f"{outcome}: {draw(targets)}"
            if draw(st.booleans()):
                arcs += f", error: {draw(targets)}"
            lines.append(f"  {name}: {{do: {call}, with: {given}, on: {{{arcs}}}}}")
        else:
            calls = [t for t in names if t != name]
            then = draw(st.sampled_from(calls or ["done"]))
            limit = draw(st.integers(-1, 5))
            lines.append(f"  {name}:")
            lines.append("    choose:")
            lines.append(f'      - {{if: "vars.n < {limit}", then: {then}}}')
            lines.append(f"      - {{else: {draw(st.sampled_from(['done', 'failure']))}}}")
    return "\n".join(line for line in lines if line) + "\n"


@FUZZ
@given(machines(), st.sampled_from(["robot", "a,b"]))
def test_random_valid_machines_run_to_an_end(text: str, agents: str) -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "m.yaml"
        path.write_text(text, encoding="utf-8")
        code, out, err = hfsm_run(str(path), "--world", "none", "--agents", agents, "--max-time", "60")
    assert "Traceback" not in err, err
    if code == 2:  # a choice cycle the generator made (E313): a finding, not a run
        assert_findings_only(code, err.replace("\n", "\n"), path)
        assert "E313" in err, err
        return
    assert code in (0, 1), err
    assert out.count(": ended in") + out.count(": did not end") == len(agents.split(","))


def test_a_value_of_many_lines_is_quoted_on_one_line() -> None:
    """Found by the mutation above: a block scalar where a number or a name belongs."""
    check('outcomes: [done]\ntimer: >\n  look:\n    do: wait\nstates:\n  "a\\nb": {do: wait, on: {done: done}}\n')
