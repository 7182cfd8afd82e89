"""Properties over random valid machines: the interpreter never crashes, every `enter` has its
`exit` (last in, first out), and a machine timer always ends a loop."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml
from helpers import execute
from hypothesis import given
from hypothesis import strategies as st

OUTCOMES = ["done", "failure"]
KINDS = ["wait", "wait_forever", "set", "log", "send", "wait_for", "choice", "child"]


@st.composite
def machines(draw: st.DrawFn) -> tuple[dict[str, Any], float | None]:
    n = draw(st.integers(1, 6))
    names = [f"s{i}" for i in range(n)]
    kinds = [draw(st.sampled_from(KINDS)) for _ in names]
    plain = [s for s, k in zip(names, kinds, strict=True) if k != "choice"]
    timer = draw(st.one_of(st.none(), st.sampled_from([0.05, 0.3, 1.0, 2.5])))
    states = {name: _state(draw, kind, names, plain) for name, kind in zip(names, kinds, strict=True)}
    machine: dict[str, Any] = {"vars": {"n": 0}, "outcomes": OUTCOMES, "receives": ["poke"], "states": states}
    if timer is not None:
        machine["timer"] = timer
    if draw(st.booleans()):
        machine["any"] = {"poke": draw(st.sampled_from(names + OUTCOMES))}
    return machine, timer


def _state(draw: st.DrawFn, kind: str, names: list[str], plain: list[str]) -> dict[str, Any]:
    def target(pool: list[str] = names) -> str:
        return str(draw(st.sampled_from(pool + OUTCOMES)))

    if kind == "choice":
        return {
            "choose": [
                {"if": f"vars.n % 3 == {draw(st.integers(0, 2))}", "then": target(plain)},
                {"else": target(plain)},
            ]
        }
    state: dict[str, Any]
    if kind == "wait":
        state = {
            "do": "wait",
            "with": {"seconds": draw(st.sampled_from([0, 0.05, 0.12, 0.5]))},
            "on": {"done": target()},
        }
    elif kind == "wait_forever":
        state = {
            "do": "wait",
            "timer": draw(st.sampled_from([0.1, 0.4])),
            "on": {"done": target(), "timeout": target()},
        }
    elif kind == "set":
        state = {"do": "set", "with": {"n": "${vars.n + 1}"}, "on": {"done": target()}}
    elif kind == "log":
        state = {"do": "log", "with": {"text": "n=${vars.n}"}, "on": {"done": target()}}
    elif kind == "send":
        state = {"do": "send", "with": {"message": "poke"}, "on": {"sent": target()}}
    elif kind == "wait_for":
        state = {
            "do": "wait_for",
            "with": {"message": "poke"},
            "timer": 0.3,
            "on": {"received": target(), "timeout": target()},
        }
    else:
        state = {"do": "child", "on": {"finished": target(), "timeout": target()}}
    if draw(st.booleans()) and kind not in ("wait_forever", "wait_for", "child"):
        state["on"]["error"] = target()
    return state


CHILD = {
    "outcomes": ["finished"],
    "timer": 0.7,
    "states": {
        "a": {"do": "wait", "with": {"seconds": 0.1}, "on": {"done": "b"}},
        "b": {"do": "wait", "with": {"seconds": 0.2}, "on": {"done": "a"}},
    },
}


def _run(tmp_path: Path, machine: dict[str, Any], max_time: float) -> tuple[Any, list[dict[str, Any]]]:
    (tmp_path / "child.yaml").write_text(yaml.safe_dump(CHILD))
    (tmp_path / "top.yaml").write_text(yaml.safe_dump(machine, sort_keys=False))
    return execute(tmp_path / "top.yaml", agents=["a", "b"], max_time=max_time)


def _check_nesting(records: list[dict[str, Any]]) -> None:
    stacks: dict[str, list[list[str]]] = {}
    for record in records:
        stack = stacks.setdefault(record["agent"], [])
        if record["kind"] == "enter":
            stack.append(record["path"])
        elif record["kind"] == "exit":
            assert stack and stack[-1] == record["path"], (stack, record)
            stack.pop()
    assert all(not s for s in stacks.values()), stacks


@given(machines())
def test_never_crashes_and_every_enter_has_its_exit(
    tmp_path_factory: Any, drawn: tuple[dict[str, Any], Any]
) -> None:
    machine, _ = drawn
    result, records = _run(tmp_path_factory.mktemp("m"), machine, max_time=5)
    assert set(result.agents) == {"a", "b"}
    _check_nesting(records)


@given(machines().filter(lambda drawn: drawn[1] is not None))
def test_a_machine_timer_always_ends_the_run(
    tmp_path_factory: Any, drawn: tuple[dict[str, Any], float]
) -> None:
    machine, timer = drawn
    result, _ = _run(tmp_path_factory.mktemp("m"), machine, max_time=timer + 5)
    if result.error:
        assert "state entries in one tick" in result.error or "division" in result.error, result.error
    else:
        assert all(r.outcome is not None and r.time <= timer + 1e-9 for r in result.agents.values())
