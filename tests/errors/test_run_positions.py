"""A run-time error inside an expression points at that expression: the `${…}` of a `with:` value (at
any depth of a dict, a list or a text of several), a guard, a watch (the state's or the machine's), a
timer, a retry's times or delay, a called machine's own `outputs:` or `timer:` (in that machine's file):
its line and column, and the caret under it."""

from __future__ import annotations

from pathlib import Path

import pytest

from hfsm.cli.run import main

RUN = Path(__file__).resolve().parent / "run"

# file: (line, column, the characters the caret underlines)
CASES = {
    "index_error.yaml": (6, 22, '${vars.items[5]}'),
    "text_second_expression.yaml": (11, 32, "${vars.items[5]}"),
    "send_data.yaml": (6, 82, "${vars.items[3]}"),
    "region_nested.yaml": (7, 49, "${vars.items[7]}"),
    "expression_error.yaml": (10, 13, "1 / vars.zero > 1"),
    "state_watch.yaml": (8, 13, '"state.time > 0.5 and 1 / vars.zero > 0"'),
    "machine_watch.yaml": (4, 9, '"vars.n > 5 and 1 / vars.zero > 0"'),
    "state_timer.yaml": (6, 13, "${vars.items[2]}"),
    "retry_times.yaml": (9, 33, "${1 // params.zero}"),
    "retry_delay.yaml": (11, 15, "${1 / params.zero}"),
    "callee_outputs.yaml": (6, 9, "${vars.items[5]}"),
    "outputs_fail.yaml": (6, 9, "${vars.items[5]}"),
    "callee_timer.yaml": (5, 9, "${1 / params.zero}"),
}
IN = {"callee_outputs.yaml": "outputs_fail.yaml", "callee_timer.yaml": "timer_fail.yaml"}  # the file at fault


@pytest.mark.parametrize("name", sorted(CASES))
def test_a_run_time_error_points_at_the_expression_that_failed(
    name: str, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(RUN)
    monkeypatch.setenv("NO_COLOR", "1")
    line, col, under = CASES[name]
    assert main([name, "--world", "none", "--quiet"]) == 1
    printed = capsys.readouterr().err.splitlines()
    file = IN.get(name, name)
    assert printed[0].startswith(f"{file}:{line}:{col}: error: robot at t=")
    source = (RUN / file).read_text(encoding="utf-8").splitlines()[line - 1]
    assert printed[2].endswith(source)
    carets = printed[3].split("| ", 1)[1]
    assert carets == " " * (col - 1) + "^" * len(under)
    assert source[col - 1 : col - 1 + len(under)] == under
