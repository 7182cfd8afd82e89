"""Scopes at run time (docs/REFERENCE.md#scopes): what primitives and parallel regions see under a scope, where
`scope.*` reads which scope, and a property: pairs of any size never hear each other."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.primitive import Context, Outcome, primitive
from hfsm.registry import Registry
from tests.helpers import execute, write


@primitive(outcomes=["heard"], outputs=["scope", "sender"])
def ping_pong(ctx: Context) -> Outcome:
    """Say `ping`, then wait for the other's `ping` (a primitive's own radio, under its scope)."""
    ctx.send("ping")
    ctx.wait_until(lambda: _got(ctx))
    return Outcome("heard", scope=ctx.scope, sender=_seen[ctx.agent])


_seen: dict[str, str] = {}


def _got(ctx: Context) -> bool:
    message = ctx.receive("ping")
    if message is not None:
        _seen[ctx.agent] = message.sender
    return ctx.agent in _seen


def test_a_primitive_sends_and_receives_under_its_scope(tmp_path: Path) -> None:
    _seen.clear()
    top = write(
        tmp_path,
        "duo",
        """
        outcomes: [done]
        vars: {scope: "", sender: ""}
        outputs: {scope: "${vars.scope}", sender: "${vars.sender}"}
        states:
          talk:
            do: ping_pong
            scope: {name: "${'pair_' + ('ab' if agent.id in ['a', 'b'] else 'cd')}",
                    agents: "${['a', 'b'] if agent.id in ['a', 'b'] else ['c', 'd']}"}
            timer: 1
            save: {scope: scope, sender: sender}
            on: {heard: done, timeout: done}
        """,
    )
    result, records = execute(top, agents=("a", "b", "c", "d"), registry=Registry([ping_pong]))
    got = {name: (r.outputs["scope"], r.outputs["sender"]) for name, r in result.agents.items()}
    assert got == {"a": ("pair_ab", "b"), "b": ("pair_ab", "a"), "c": ("pair_cd", "d"), "d": ("pair_cd", "c")}
    assert {r["message"] for r in records if r["kind"] == "send"} == {"pair_ab/ping", "pair_cd/ping"}


def test_regions_run_under_their_parallel_states_scope_and_watches_under_the_machines(tmp_path: Path) -> None:
    write(
        tmp_path,
        "where",
        'outcomes: [done]\noutputs: {at: "${scope.name}"}\nstates:\n  a: {do: log, with: {text: x}, on: {done: done}}\n',
    )
    top = write(
        tmp_path,
        "outer",
        """
        outcomes: [done, watched]
        vars: {one: "", two: "", given: ""}
        outputs: {one: "${vars.one}", two: "${vars.two}", given: "${vars.given}", mine: "${scope.name}"}
        states:
          both:
            scope: {name: crew, agents: []}
            parallel:
              one: {do: where, save: {one: at}}
              two: {do: set, with: {given: "${scope.name}"}}
            join: [{else: watch}]
          watch:
            do: wait
            scope: {name: other, agents: []}
            with: {seconds: 1}
            watch:
              - if: "scope.name == 'other'"
                then: watched
            on: {done: done}
        """,
    )
    result, _ = execute(top)
    robot = result.agents["robot"]
    assert robot.outcome == "done"  # the watch reads the machine's scope (none), not the state's
    assert robot.outputs == {"one": "crew", "two": "", "given": "crew", "mine": ""}


MEET = """
outcomes: [met]
vars: {arrived: []}
outputs: {arrived: "${vars.arrived}"}
states:
  m: {do: barrier, with: {name: here}, save: {arrived: arrived}, on: {passed: met}}
"""
TEAMS = """
params: {team: {type: dict}, mates: {type: dict}}
outcomes: [met]
vars: {arrived: []}
outputs: {arrived: "${vars.arrived}"}
states:
  t:
    do: meet
    scope: {name: "${'team_' + params.team[agent.id]}", agents: "${params.mates[agent.id]}"}
    save: {arrived: arrived}
    on: {met: met}
"""


@settings(max_examples=15, deadline=None)
@given(st.lists(st.integers(min_value=1, max_value=3), min_size=1, max_size=3))
def test_teams_of_any_size_meet_only_their_own(tmp_path_factory: pytest.TempPathFactory, sizes: list[int]) -> None:
    """Every team under its own scope runs one barrier of one name: each hears its own team only."""
    folder = tmp_path_factory.mktemp("teams")
    names = [f"a{t}x{i}" for t, size in enumerate(sizes) for i in range(size)]
    team = {name: name.split("x")[0] for name in names}
    mates = {n: [m for m in names if team[m] == team[n]] for n in names}  # the agent itself listed too
    write(folder, "meet", MEET)
    top = write(folder, "teams", TEAMS)
    result, _ = execute(top, agents=tuple(names), params={"team": team, "mates": mates})
    for name in names:
        assert result.agents[name].outputs["arrived"] == [m for m in mates[name] if m != name]
