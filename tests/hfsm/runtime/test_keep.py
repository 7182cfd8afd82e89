"""`send`'s `keep` (docs/REFERENCE.md#statuses-keep-last): a status replaces the sender's copy not yet
taken, an event keeps every copy; a message to an agent that has ended is not kept; a `receive`
record names its `send` by `id`."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hfsm.primitive import Context, primitive
from hfsm.registry import Registry
from tests.helpers import execute, sender_states, write

TALK = """
params:
  keep: {type: str, default: all}
  times: {type: int, default: 5}
vars: {n: 0, got: [], first: -1}
outcomes: [done]
outputs: {got: "${vars.got}"}
states:
  who:
    choose:
      - if: "agent.id == 'a'"
        then: say
      - else: later
""" + sender_states("status", "${params.keep}") + """
  later:
    do: wait
    with: {seconds: 1}
    on: {done: take}
  take:
    do: wait_for
    with: {message: status}
    save: {first: n}
    timer: 0.1
    on: {received: keep, timeout: done}
  keep:
    do: set
    with: {got: "${vars.got + [vars.first]}"}
    on: {done: take}
"""


def _run(tmp_path: Path, keep: str, times: int = 5) -> tuple[Any, list[dict[str, Any]]]:
    return execute(write(tmp_path, "talk", TALK), agents=("a", "b"), params={"keep": keep, "times": times})


def test_keep_all_holds_every_copy_and_keep_last_the_newest(tmp_path: Path) -> None:
    every, _ = _run(tmp_path, "all")
    assert every.agents["b"].outputs["got"] == [0, 1, 2, 3, 4]
    last, records = _run(tmp_path, "last")
    assert last.agents["b"].outputs["got"] == [4]
    received = [r for r in records if r["kind"] == "receive"]
    assert [r.get("replaced", False) for r in received] == [False, True, True, True, True]


def test_a_receive_names_its_send_by_id_and_the_data_are_the_sends(tmp_path: Path) -> None:
    _, records = _run(tmp_path, "last")
    sends = {r["id"]: r for r in records if r["kind"] == "send"}
    assert sorted(sends) == [1, 2, 3, 4, 5]
    assert all(r["keep"] == "last" for r in sends.values())
    for r in records:
        if r["kind"] == "receive":
            assert "data" not in r and sends[r["id"]]["message"] == r["message"] == "status"
            assert sends[r["id"]]["t"] < r["t"]


def test_a_bad_keep_is_an_error_at_run_time(tmp_path: Path) -> None:
    result, _ = _run(tmp_path, "lats")
    assert result.error is not None and "keep must be 'all' or 'last', not 'lats'" in result.error


def test_messages_to_an_agent_that_has_ended_are_not_kept(tmp_path: Path) -> None:
    top = write(tmp_path, "late", """
        outcomes: [done]
        states:
          who:
            choose:
              - if: "agent.id == 'a'"
                then: pause
              - else: done
          pause:
            do: wait
            with: {seconds: 0.5}
            on: {done: tell}
          tell:
            do: send
            with: {message: late, to: b}
            on: {sent: done}
        """)
    result, records = execute(top, agents=("a", "b"))
    assert result.agents["b"].outcome == "done"
    assert [r["kind"] for r in records if r["kind"] in ("send", "receive")] == ["send"]


@settings(max_examples=20, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["a", "c"]), st.sampled_from(["all", "last"])), min_size=1, max_size=8))
def test_a_receiver_holds_the_newest_status_of_each_sender_and_every_event(
    tmp_path_factory: pytest.TempPathFactory, sends: list[tuple[str, str]]
) -> None:
    """Senders a and c send a mix of events and statuses (one a tick) to b, which reads them all
    later: a status takes the place of every copy from its sender not yet taken, at the end."""
    folder = tmp_path_factory.mktemp("keep")
    plan = {who: [keep for w, keep in sends if w == who] for who in ("a", "c")}
    top = write(folder, "mix", MIX.replace("PLAN", json.dumps(plan)))
    result, _ = execute(top, agents=("a", "b", "c"))
    expected: list[list[Any]] = []  # the model of b's mailbox: [sender, i]
    for tick in range(8):
        for who in ("a", "c"):
            if tick < len(plan[who]):
                if plan[who][tick] == "last":
                    expected = [m for m in expected if m[0] != who]
                expected.append([who, tick])
    assert result.agents["b"].outputs["got"] == expected


MIX = """
params:
  plan: {type: dict, default: PLAN}
vars: {i: 0, got: [], one: "", n: 0}
outcomes: [done]
outputs: {got: "${vars.got}"}
states:
  who:
    choose:
      - if: "agent.id == 'b'"
        then: later
      - else: more
  more:
    choose:
      - if: "vars.i < len(params.plan[agent.id])"
        then: say
      - else: done
  say:
    do: send
    with: {message: news, to: b, keep: "${params.plan[agent.id][vars.i]}", data: {i: "${vars.i}"}}
    on: {sent: step}
  step:
    do: set
    with: {i: "${vars.i + 1}"}
    on: {done: pause}
  pause:
    do: wait
    with: {seconds: 0.05}
    on: {done: more}
  later:
    do: wait
    with: {seconds: 1}
    on: {done: take}
  take:
    do: wait_for
    with: {message: news}
    save: {one: sender, n: i}
    timer: 0.1
    on: {received: keep, timeout: done}
  keep:
    do: set
    with: {got: "${vars.got + [[vars.one, vars.n]]}"}
    on: {done: take}
"""


@primitive(outcomes=["said"])
def tell_three(ctx: Context, *, keep: str = "last") -> str:
    """Say `status` three times, a tick apart, as `keep`."""
    for n in range(3):
        ctx.send("status", to="b", keep=keep, n=n)
        ctx.wait()
    return "said"


def test_a_primitive_sends_a_status_and_a_bad_keep_is_its_error(tmp_path: Path) -> None:
    top = write(tmp_path, "prim", """
        params:
          keep: {type: str, default: last}
        vars: {got: [], one: -1}
        outcomes: [done]
        outputs: {got: "${vars.got}"}
        states:
          who:
            choose:
              - if: "agent.id == 'a'"
                then: tell
              - else: later
          tell:
            do: tell_three
            with: {keep: "${params.keep}"}
            on: {said: done}
          later:
            do: wait
            with: {seconds: 0.5}
            on: {done: take}
          take:
            do: wait_for
            with: {message: status}
            save: {one: n}
            timer: 0.1
            on: {received: keep, timeout: done}
          keep:
            do: set
            with: {got: "${vars.got + [vars.one]}"}
            on: {done: take}
        """)
    result, _ = execute(top, agents=("a", "b"), registry=Registry([tell_three]))
    assert result.agents["b"].outputs["got"] == [2]
    result, _ = execute(top, agents=("a", "b"), params={"keep": "newest"}, registry=Registry([tell_three]))
    assert result.error is not None and "keep must be 'all' or 'last', not 'newest'" in result.error
