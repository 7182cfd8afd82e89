"""`hfsm-test` as users meet it: test files run, fail at their positions, and are checked (exit 2)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from helpers import finding_lines

from hfsm.cli.test import main

ROOT = Path(__file__).resolve().parents[3]

PING = """
    doc: Say ping, wait for pong (or give up), count the tries.
    params:
      tries: {type: int, default: 3}
    vars: {n: 0, got: ""}
    outcomes: [ponged, gave_up]
    outputs: {n: "${vars.n}", got: "${vars.got}"}
    receives: [stop]
    any: {stop: gave_up}
    states:
      ping:
        do: send
        with: {message: ping, data: {n: "${vars.n}"}}
        on: {sent: listen}
      listen:
        do: wait_for
        with: {message: pong}
        timer: 1
        save: {got: word}
        on: {received: ponged, timeout: count}
      count:
        do: set
        with: {n: "${vars.n + 1}"}
        on: {done: again}
      again:
        choose:
          - if: "vars.n < params.tries"
            then: ping
          - else: gave_up
"""


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    return path


def hfsm_test(capsys: pytest.CaptureFixture[str], *paths: Path | str) -> tuple[int, str, str]:
    code = main([str(p) for p in paths])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def ping(tmp_path: Path) -> Path:
    return write(tmp_path, "ping.yaml", PING)


def test_passing_cases_exit_0(ping: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(
        ping.parent,
        "ping.test.yaml",
        """
        machine: ping
        agents: [a]
        tests:
          answered:
            messages: [{at: 0.3, from: b, message: pong, data: {word: hi}}]
            expect:
              outcome: ponged
              time: 0.3
              outputs: {n: 0, got: hi}
              states: [ping, listen]
              sends: [{message: ping, to: others, data: {n: 0}, at: 0}]
          unanswered:
            params: {tries: 2}
            expect:
              outcome: gave_up
              time: {min: 1.9, max: 2.1}
              outputs: {n: 2}
              states: {in_order: [listen, count, listen, count, again]}
              sends: {in_order: [ping, ping]}
          stopped:
            messages: [{at: 0.5, from: b, message: stop}]
            expect: {outcome: gave_up, time: 0.5, never: [count, again], sends: [ping]}
        """,
    )
    code, out, err = hfsm_test(capsys, path)
    assert (code, out) == (0, "")
    assert "3 passed, 0 failed" in err


def test_failures_say_what_and_where(ping: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(
        ping.parent,
        "wrong.test.yaml",
        """
        machine: ping
        tests:
          wrong:
            expect:
              outcome: ponged
              time: 1
              outputs: {n: 1}
              states: [ping, listen]
              never: [count]
              sends: [ping]
        """,
    )
    code, out, _ = hfsm_test(capsys, path)
    assert code == 1
    file = path.relative_to(Path.cwd()) if path.is_relative_to(Path.cwd()) else path
    assert out.splitlines() == [
        f"FAIL {file}::wrong",
        f'  {file}:5:16: robot: expected outcome "ponged"; it ended in "gave_up" at t = 3 s',
        f"  {file}:6:13: robot: expected to end at t = 1 s; it ended at t = 3 s",
        f"  {file}:7:20: robot: expected output n = 1, got 3",
        f"  {file}:8:15: robot: expected the states [ping, listen]; it entered "
        "[ping, listen, count, again, ping, listen, count, again, ping, listen, count, again]",
        f'  {file}:9:15: robot: expected never to enter "count"; it entered it at t = 1 s',
        f"  {file}:10:14: robot: expected 1 messages sent; it sent 3: "
        '[ping to others {"n": 0} at t = 0 s, ping to others {"n": 1} at t = 1 s, '
        'ping to others {"n": 2} at t = 2 s]',
    ]


def test_an_expected_error_and_an_unexpected_one(ping: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(
        ping.parent,
        "error.test.yaml",
        """
        machine: ping
        params: {tries: 1}
        max_time: 0.5
        tests:
          stops:
            expect: {error: "stopped at --max-time 0.5 s", outcome: null}
          surprised:
            expect: {outcome: gave_up}
        """,
    )
    code, out, _ = hfsm_test(capsys, path)
    assert code == 1
    assert "error.test.yaml::stops" not in out
    assert "error.test.yaml:8:5: the run ended in an error: stopped at --max-time 0.5 s" in out


def test_stand_ins_play_one_step_a_call_and_the_last_repeats(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write(
        tmp_path,
        "seek.yaml",
        """
        params: {limit: {type: float, default: 60}}
        vars: {seen: 0.0}
        outcomes: [found, lost]
        outputs: {seen: "${vars.seen}"}
        timer: "${params.limit}"
        states:
          look:
            do: scan_for_table
            with: {yaws: [0.0], pitch: 0.3}
            save: {seen: distance}
            on: {seen: found, not_seen: turn}
          turn:
            do: spin_on_the_spot
            with: {degrees: 90}
            on: {done: look}
        """,
    )
    path = write(
        tmp_path,
        "seek.test.yaml",
        """
        machine: seek
        stand_ins:
          spin_on_the_spot: {after: 2, outcome: done}
          scan_for_table:
            - {after: 1, outcome: not_seen}
            - {after: 1, outcome: not_seen}
            - {after: 0.5, outcome: seen, outputs: {distance: 1.5}}
        tests:
          third_look_sees:
            expect:
              outcome: found
              time: 6.5
              outputs: {seen: 1.5}
              calls: {scan_for_table: 3, spin_on_the_spot: 2}
          never_seen:
            params: {limit: 10}
            stand_ins:
              scan_for_table: {after: 1, outcome: not_seen}
            expect: {outcome: timeout, time: 10, calls: {scan_for_table: 4}}
          hangs:
            params: {limit: 3}
            stand_ins:
              scan_for_table: {doc: a scan that never ends by itself}
            expect: {outcome: timeout, time: 3, states: [look], calls: {spin_on_the_spot: 0}}
        """,
    )
    code, out, err = hfsm_test(capsys, path)
    assert code == 0, out
    assert "3 passed" in err


def test_inputs_over_time_and_messages_to_each_agent(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write(
        tmp_path,
        "door.yaml",
        """
        outcomes: [through, waited]
        states:
          nap: {do: wait, with: {seconds: 1}, on: {done: look}}
          look:
            choose:
              - {if: "in.door_open and in.width > 0.5", then: through}
              - else: hear
          hear: {do: wait_for, with: {message: go}, on: {received: waited}}
        """,
    )
    path = write(
        tmp_path,
        "door.test.yaml",
        """
        machine: door
        agents: [a, b]
        inputs:
          - {in: {door_open: false, width: 0.8}}
          - {at: 0.5, agent: a, in: {door_open: true}}
          - {at: 2, in: {door_open: true}}
        messages:
          - {at: 3, from: c, message: go}
        tests:
          only_a_sees_it_open:
            expect:
              agents:
                a: {outcome: through, time: 1}
                b: {outcome: waited, time: 3, states: [nap, look, hear]}
          the_door_opens_later:
            inputs: [{at: 0, in: {door_open: false, width: 0.8}}, {at: 0.95, in: {door_open: true}}]
            messages: [{at: 0, from: b, message: go, to: a}]
            expect:
              agents:
                a: {outcome: through}
                b: {outcome: through, states: {in_order: [look]}}
        """,
    )
    code, out, _ = hfsm_test(capsys, path)
    assert (code, out) == (0, "")


def test_bad_test_files_exit_2_with_every_problem_at_its_position(
    ping: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = write(
        ping.parent,
        "bad.test.yaml",
        """
        machine: ping
        agents: [a]
        params: {trys: 2}
        stand_ins:
          wait_for: {outcome: received}
          scan_for_table: {outcome: seen}
        tests:
          one:
            messages: [{from: b, message: pong, to: c}]
            expect:
              outcome: pong
              outputs: {count: 1}
              states: [listen/x, lisen]
              agents: {b: {outcome: ponged}}
              calls: {send: 1}
          two:
            machine: pingg
            expect: {}
        """,
    )
    code, out, err = hfsm_test(capsys, path)
    assert (code, out) == (2, "")
    file = path.relative_to(Path.cwd()) if path.is_relative_to(Path.cwd()) else path
    assert finding_lines(err) == [
        f"{file}:3:10: error[T303]: 'ping' has no param 'trys'; did you mean 'tries'?",
        f"{file}:5:3: error[T310]: 'wait_for' is a built-in: script what it waits for, not the built-in",
        f"{file}:9:45: error[T311]: no agent 'c' in this test",
        f"{file}:11:16: error[T321]: 'ping' has no outcome 'pong'; did you mean 'ponged'?",
        f"{file}:12:17: error[T321]: 'ping' has no output 'count' (it has: n, got)",
        f"{file}:13:16: error[T322]: 'listen' calls 'wait_for', which has no states",
        f"{file}:13:26: error[T322]: 'ping' has no state 'lisen'; did you mean 'listen'?",
        f"{file}:14:16: error[T320]: no agent 'b' in this test (agents: a)",
        f"{file}:15:15: error[T323]: calls are recorded for stand-ins only: 'send' is not one "
        "(stand-ins: scan_for_table)",
        f"{file}:17:14: error[T302]: no machine 'pingg' in {_shown(ping.parent)}, {_shown(ROOT / 'machines')}; "
        "did you mean 'ping'?",
    ]


def _shown(path: Path) -> str:
    return str(path.relative_to(Path.cwd()) if path.is_relative_to(Path.cwd()) else path)


def test_a_world_primitive_left_without_a_stand_in_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = write(
        tmp_path,
        "lift.test.yaml",
        """
        machine: synchronised_lift_table
        params: {role: leader}
        tests:
          no_lift:
            expect: {outcome: lifted}
        """,
    )
    code, _, err = hfsm_test(capsys, path)
    assert code == 2
    assert finding_lines(err)[-1].endswith(
        "lift.test.yaml:1:10: error[T313]: 'synchronised_lift_table' calls primitives of world 'sim' with "
        "no stand-in: lift_table; add each to `stand_ins:` (tests run without a world)"
    )


def test_schema_errors_and_missing_paths(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, "shape.test.yaml", "machine: ping\ntests:\n  one: {expect: {outcom: x}}\n")
    code, _, err = hfsm_test(capsys, path, tmp_path / "nowhere.test.yaml")
    assert code == 2
    assert "shape.test.yaml:3:18: error[E200]: unknown key 'outcom'; did you mean 'outcome'?" in err
    assert "nowhere.test.yaml:1:1: error[T100]: no such file or folder" in err
    assert hfsm_test(capsys)[0] == 2


def test_committed_schema_is_current(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = hfsm_test(capsys, "--schema")
    assert code == 0
    assert (ROOT / "docs" / "test.schema.json").read_text() == out, (
        "run: hfsm-test --schema > docs/test.schema.json"
    )


def test_agents_that_fail(ping: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(
        ping.parent,
        "fail.test.yaml",
        """
        machine: ping
        agents: [a, b]
        params: {tries: 1}
        fail: [{agent: b, at: 0.5, reason: battery}]
        tests:
          b_goes_silent:
            expect:
              agents:
                a: {outcome: gave_up, time: 1, failed: false}
                b: {outcome: null, failed: true, time: 0.5}
          nobody_fails:
            fail: []
            expect: {failed: true}
        """,
    )
    code, out, _ = hfsm_test(capsys, path)
    assert code == 1
    assert "b_goes_silent" not in out
    assert "fail.test.yaml:13:22: a: expected to fail; it did not" in out
    assert "fail.test.yaml:13:22: b: expected to fail; it did not" in out


def test_machines_by_path_and_by_lib_and_picking_cases(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "tests").mkdir()
    write(
        tmp_path / "lib",
        "nap.yaml",
        "outcomes: [done]\nstates:\n  a: {do: wait, with: {seconds: 1}, on: {done: done}}\n",
    )
    write(
        tmp_path / "lib",
        "twice.yaml",
        "outcomes: [done]\nstates:\n  a: {do: nap, on: {done: b}}\n  b: {do: nap, on: {done: done}}\n",
    )
    path = write(
        tmp_path / "tests",
        "nap.test.yaml",
        """
        lib: [../lib]
        tests:
          by_name:
            machine: twice
            expect: {outcome: done, time: 2, states: [a, a/a, b, b/a]}
          by_path:
            machine: ../lib/nap.yaml
            expect: {time: 1}
          nothing_to_test:
            expect: {}
        """,
    )
    code, _, err = hfsm_test(capsys, path)
    assert code == 2
    assert finding_lines(err)[-1].endswith(
        "nap.test.yaml:9:3: error[T300]: no machine to test: give `machine:` here or at the top of the file"
    )
    path.write_text(path.read_text().replace("  nothing_to_test:\n    expect: {}\n", ""))
    assert main([str(tmp_path), "-k", "by_"]) == 0
    assert "2 passed, 0 failed (2 cases in 1 files" in capsys.readouterr().err
    assert main([str(path), "-k", "path", "-v"]) == 0
    assert capsys.readouterr().out.endswith("nap.test.yaml::by_path\n")


def test_messages_scripted_and_expected_under_a_scope(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write(
        tmp_path,
        "ask.yaml",
        """
        outcomes: [answered]
        vars: {said: ""}
        outputs: {said: "${vars.said}"}
        states:
          ask: {do: send, with: {message: question}, on: {sent: hear}}
          hear: {do: wait_for, with: {message: answer}, save: {said: text}, on: {received: answered}}
        """,
    )
    write(
        tmp_path,
        "pair_up.yaml",
        """
        outcomes: [done]
        vars: {said: ""}
        outputs: {said: "${vars.said}"}
        states:
          talk:
            do: ask
            scope: {name: pair, agents: []}
            save: {said: said}
            on: {answered: done}
        """,
    )
    path = write(
        tmp_path,
        "pair_up.test.yaml",
        """
        machine: pair_up
        agents: [a]
        tests:
          scoped:
            messages:
              - {at: 0.1, from: b, message: answer, data: {text: plain}}
              - {at: 0.5, from: b, scope: pair, message: answer, data: {text: scoped}}
            expect:
              outcome: done
              time: 0.5
              outputs: {said: scoped}
              sends: [{message: question, scope: pair, to: others}]
          unscoped_expectation_fails:
            messages: [{at: 0.5, from: b, scope: pair, message: answer, data: {text: scoped}}]
            expect: {sends: [question]}
        """,
    )
    code, out, err = hfsm_test(capsys, path)
    assert code == 1
    assert "1 passed, 1 failed" in err
    assert "expected message 1 sent to be question, got pair/question to others" in out
