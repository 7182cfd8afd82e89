"""`wait_for` with `all: true` (docs/REFERENCE.md#built-ins): every message of that name then in the
mailbox taken at once, oldest first, as `messages`; none left for the next `wait_for`; without `all`
one at a time, as before."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import execute, sender_states, write

TALK = """
params:
  times: {type: int, default: 3}
  all: {type: bool, default: true}
vars: {n: 0, got: [], left: -1}
outcomes: [done]
outputs: {got: "${vars.got}", left: "${vars.left}"}
states:
  who:
    choose:
      - if: "agent.id == 'b'"
        then: later
      - else: say
""" + sender_states("news") + """
  later:
    do: wait
    with: {seconds: 1}
    on: {done: how}
  how:
    choose:
      - if: "params.all"
        then: take
      - else: one
  take:
    do: wait_for
    with: {message: news, all: true}
    timer: 0.1
    save: {got: messages}
    on: {received: rest, timeout: done}
  one:
    do: wait_for
    with: {message: news}
    timer: 0.1
    save: {left: n}
    on: {received: rest, timeout: done}
  rest:
    do: wait_for
    with: {message: news}
    timer: 0.1
    save: {left: n}
    on: {received: done, timeout: done}
"""


def _run(tmp_path: Path, senders: tuple[str, ...], every: bool, times: int = 3) -> Any:
    top = write(tmp_path, "talk", TALK)
    result, _ = execute(top, agents=(*senders, "b"), params={"all": every, "times": times})
    return result.agents["b"].outputs


def test_all_takes_every_message_waiting_oldest_first_and_leaves_none(tmp_path: Path) -> None:
    got = _run(tmp_path, ("a",), True)
    assert got["got"] == [{"n": 0, "sender": "a"}, {"n": 1, "sender": "a"}, {"n": 2, "sender": "a"}]
    assert got["left"] == -1


def test_without_all_one_message_is_taken(tmp_path: Path) -> None:
    got = _run(tmp_path, ("a",), False)
    assert got["got"] == [] and got["left"] == 1  # the second of three: one taken by each wait_for


@settings(max_examples=10, deadline=None)
@given(st.integers(1, 5), st.sampled_from([("a",), ("a", "c")]))
def test_all_takes_as_many_as_were_sent(tmp_path_factory: Any, times: int, senders: tuple[str, ...]) -> None:
    got = _run(tmp_path_factory.mktemp("all"), senders, True, times)
    assert len(got["got"]) == times * len(senders)
    for sender in senders:
        assert [m["n"] for m in got["got"] if m["sender"] == sender] == list(range(times))
