"""`hfsm-test`'s team settings: params for one agent (`agent_params`), and scripted partners that
meet the agents at barriers (`partners`, docs/REFERENCE.md#barriers)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from helpers import finding_lines

from hfsm.cli.test import main

ROOT = Path(__file__).resolve().parents[3]

ROLE = """
    params:
      role: {type: str}
      pause: {type: float, default: 1}
    outcomes: [led, helped]
    states:
      nap:
        do: wait
        with: {seconds: "${params.pause}"}
        on: {done: which}
      which:
        choose:
          - if: "params.role == 'leader'"
            then: led
          - else: helped
"""

MEET = f"machine: {ROOT / 'examples' / 'meet.yaml'}\n"


def write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    return path


def hfsm_test(capsys: pytest.CaptureFixture[str], path: Path) -> tuple[int, str, str]:
    code = main([str(path), "-v"])
    out, err = capsys.readouterr()
    return code, out, err


def test_params_for_one_agent_over_those_for_all(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write(tmp_path, "role.yaml", ROLE)
    path = write(
        tmp_path,
        "role.test.yaml",
        """
        machine: role
        agents: [a, b]
        agent_params: {a: {role: leader}}       # a required param given to each agent apart
        tests:
          each_its_role:
            agent_params: {b: {role: helper, pause: 2}}
            expect:
              agents:
                a: {outcome: led, time: 1}
                b: {outcome: helped, time: 2}
          one_for_all_and_one_apart:
            params: {role: helper, pause: 0.5}
            agent_params: {}
            expect:
              agents:
                a: {outcome: led, time: 0.5}
                b: {outcome: helped, time: 0.5}
        """,
    )
    code, out, err = hfsm_test(capsys, path)
    assert code == 0, out + err


def test_a_scripted_partner_meets_the_agents_at_a_barrier(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = write(
        tmp_path,
        "meet.test.yaml",
        MEET
        + """
        agents: [a]
        tests:
          it_arrives_after_the_agent:       # a waits from 1 s; the partner's notice comes at 3.05
            partners: [{agent: r2, barrier: lift, at: 3}]
            expect: {outcome: lifted, time: 3.55, outputs: {partners: [r2]}}
          it_is_there_first:                # a holds its notice already: passes the tick after 1 s
            partners: [{agent: r2, barrier: lift, at: 0.5}]
            expect: {outcome: lifted, time: 1.55, outputs: {partners: [r2]}}
          with_another_agent:
            agents: [a, b]
            partners: [{agent: r2, barrier: lift, at: 2}]
            expect:
              outcome: lifted
              agents:
                a: {time: 3.05, outputs: {partners: [b, r2]}}
                b: {time: 3.05, outputs: {partners: [a, r2]}}
          at_another_barrier:               # a member of the run that never comes: the timer fires
            partners: [{agent: r2, barrier: push, at: 0}]
            expect: {outcome: alone, time: 11}
        """.replace("\n        ", "\n"),
    )
    code, out, err = hfsm_test(capsys, path)
    assert code == 0, out + err


def test_team_settings_are_checked(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    write(tmp_path, "role.yaml", ROLE)
    path = write(
        tmp_path,
        "bad.test.yaml",
        """
        machine: role
        agents: [a, b]
        agent_params: {a: {role: leader}, c: {role: x}}
        partners: [{agent: b, barrier: lift, at: 1}]
        tests:
          one:
            agent_params: {a: {roel: 1}}
            expect: {}
        """,
    )
    code, out, err = hfsm_test(capsys, path)
    assert (code, out) == (2, "")
    name = path.name
    lines = [line.split(name, 1)[1] for line in finding_lines(err)]
    assert lines == [
        ":3:35: error[T311]: no agent 'c' in this test (agents: a, b)",
        ":4:20: error[T314]: 'b' is an agent of the test: a partner is a team mate the test scripts",
        ":6:3: error[T303]: 'role' needs param 'role' (str): give it in `params:`",  # b has none
        ":7:24: error[T303]: 'role' has no param 'roel'; did you mean 'role'?",
    ]
