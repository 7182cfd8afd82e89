"""Malformed v2 files (docs/REFERENCE.md: hfsm-run, parallel states, watches and retries): `hfsm-run --check` finds every error in one pass, each at
its `FILE:LINE:COL` (the offending key or value) with its code and, for a misspelt name, a
suggestion; exit 2, no traceback. Each file's first line says what is wrong and where the reference
forbids it; the stand-in behaviours come from tests/spec/cases/ through `--lib`."""

from __future__ import annotations

from pathlib import Path

import pytest

from hfsm.cli.run import main

HERE = Path(__file__).resolve().parent
MALFORMED = HERE / "malformed"

# file -> every error, in order: (LINE:COL, code, a part of its message)
ERRORS: dict[str, list[tuple[str, str, str]]] = {
    "all_background": [("5:5", "E324", "'search'")],
    "attempt_in_times": [("6:40", "E331", "'state.attempt'")],
    "barrier_no_name": [("5:9", "E307", "'barrier'"), ("7:12", "E310", "'on'")],
    "barrier_params": [
        ("6:32", "E306", "'agents'"),
        ("6:45", "E306", "'at_least'"),
        ("6:50", "E302", "'round'"),
    ],
    "else_not_last": [("7:5", "E320", "detect=not_found"), ("8:9", "E311", "'else'")],
    "if_list": [("6:13", "E200", "'if'")],
    "input_missing": [("8:14", "E330", "no input 'in.battery'")],
    "join_background": [("9:16", "E322", "'head'")],
    "join_bad_outcome": [("8:24", "E323", "did you mean 'found'?")],
    "join_hang": [("8:5", "E320", "detect=not_found, explore=finished")],
    "join_unknown_region": [("9:16", "E321", "did you mean 'detect'?")],
    "machine_time_timer": [("3:11", "E331", "'machine.time'")],
    "many": [
        ("8:21", "E300", "did you mean 'exploration'?"),
        ("9:42", "E302", "'tme'"),
        ("9:58", "E304", "did you mean 'pose'?"),
        ("12:15", "E301", "did you mean 'done'?"),
        ("14:12", "E310", "'on'"),
        ("17:14", "E314", "did you mean 'state.time'?"),
    ],
    "parallel_do": [("5:5", "E200", "a parallel state has no 'do'")],
    "parallel_on_outcome": [("9:10", "E303", "'found'")],
    "parallel_timer_unmapped": [("10:12", "E310", "'on'"), ("11:22", "E303", "did you mean 'stop'?")],
    "region_bad_name": [("6:7", "E200", "'Detect'")],
    "region_save_unknown": [("7:48", "E305", "did you mean 'pose'?")],
    "region_unknown_do": [("7:20", "E300", "did you mean 'detect_victim'?"), ("8:37", "E302", "'speed'")],
    "retry_no_times": [("6:12", "E200", "'times'")],
    "retry_parallel": [("9:5", "E200", "a parallel state has no 'retry'")],
    "retry_timeout_no_timer": [("7:18", "E327", "'wait'")],
    "retry_unknown": [("7:18", "E327", "did you mean 'failed'?")],
    "retry_unmapped": [("6:18", "E328", "'not_found'")],
    "scope_literals": [
        ("6:19", "E351", "'Pair-1'"),
        ("11:33", "E352", "'a, b'"),
        ("18:37", "E352", "not 7"),
        ("21:22", "E314", "did you mean 'scope.name'?"),
    ],
    "state_time_outputs": [("3:17", "E331", "'state.time'")],
    "two_saves": [("8:39", "E325", "'one'")],
    "watch_bad_target": [("5:11", "E301", "did you mean 'gave_up'?")],
    "watch_wrapped": [("8:14", "E314", "write 'state.time > 0.5'")],
    "watch_vars_in_timer": [("4:11", "E314", "'vars.t'")],
}


def test_every_malformed_file_has_its_errors() -> None:
    assert sorted(p.stem for p in MALFORMED.glob("*.yaml")) == sorted(ERRORS)


@pytest.mark.parametrize("name", sorted(ERRORS))
def test_a_malformed_file_is_refused_at_its_positions(
    name: str, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(MALFORMED)  # positions are printed relative to the working folder
    code = main([f"{name}.yaml", "--world", "none", "--check", "--lib", "../cases"])
    err = capsys.readouterr().err
    errors = [line for line in err.splitlines() if ": error[" in line]
    assert code == 2 and "Traceback" not in err
    assert len(errors) == len(ERRORS[name]), err
    for line, (position, number, part) in zip(errors, ERRORS[name], strict=True):
        assert line.startswith(f"{name}.yaml:{position}: error[{number}]: "), line
        assert part in line, line
